//! Checks that a URDF's links form one tree: unique names, joints that name existing links,
//! one parent per link, no cycle, one root.

use super::DescriptionErrorKind as Kind;
use std::collections::HashMap;

/// The tree's shape: each link's parent joint and the root link (indices as in the URDF).
#[derive(Debug)]
pub(super) struct TreeShape {
    pub(super) parent_joint: Vec<Option<usize>>,
    pub(super) root: usize,
}

/// Checks the links and joints and finds the tree's shape.
pub(super) fn tree_shape(robot: &urdf_rs::Robot) -> Result<TreeShape, Kind> {
    if robot.links.is_empty() {
        return Err(Kind::NoLinks);
    }
    let mut index = HashMap::new();
    for (i, link) in robot.links.iter().enumerate() {
        if index.insert(link.name.as_str(), i).is_some() {
            return Err(Kind::DuplicateLink {
                link: link.name.clone(),
            });
        }
    }
    let mut joint_names = HashMap::new();
    for joint in &robot.joints {
        if joint_names.insert(joint.name.as_str(), ()).is_some() {
            return Err(Kind::DuplicateJoint {
                joint: joint.name.clone(),
            });
        }
    }
    let mut parent_joint: Vec<Option<usize>> = vec![None; robot.links.len()];
    for (j, joint) in robot.joints.iter().enumerate() {
        let find = |role: &str, link: &str| {
            index.get(link).copied().ok_or_else(|| Kind::MissingLink {
                joint: joint.name.clone(),
                role: role.to_string(),
                link: link.to_string(),
            })
        };
        find("parent", &joint.parent.link)?;
        let child = find("child", &joint.child.link)?;
        if let Some(first) = parent_joint[child].replace(j) {
            return Err(Kind::TwoParents {
                link: joint.child.link.clone(),
                joints: vec![robot.joints[first].name.clone(), joint.name.clone()],
            });
        }
    }
    let parent_link =
        |link: usize| parent_joint[link].map(|j| index[robot.joints[j].parent.link.as_str()]);
    if let Some(cycle) = find_cycle(robot.links.len(), parent_link) {
        return Err(Kind::Cycle {
            links: cycle.iter().map(|&l| robot.links[l].name.clone()).collect(),
        });
    }
    let roots: Vec<usize> = (0..robot.links.len())
        .filter(|&l| parent_joint[l].is_none())
        .collect();
    match roots.as_slice() {
        [root] => Ok(TreeShape {
            parent_joint,
            root: *root,
        }),
        _ => Err(Kind::TwoRoots {
            roots: roots.iter().map(|&l| robot.links[l].name.clone()).collect(),
        }),
    }
}

/// A cycle of links following parents (the first link repeated at the end), if any.
fn find_cycle(count: usize, parent: impl Fn(usize) -> Option<usize>) -> Option<Vec<usize>> {
    for start in 0..count {
        let mut link = start;
        let mut steps = 0;
        while let Some(up) = parent(link) {
            link = up;
            steps += 1;
            if steps > count {
                // `link` is now on the cycle: walk it once round.
                let mut cycle = vec![link];
                let mut next = parent(link).expect("on a cycle");
                while next != link {
                    cycle.push(next);
                    next = parent(next).expect("on a cycle");
                }
                cycle.push(link);
                return Some(cycle);
            }
        }
    }
    None
}
