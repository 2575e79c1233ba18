//! The camera sees the whole world (issue 14, item 3): the floor, obstacle boxes and the
//! arm's own links can hide the target. The rule (docs/SENSING.md): the ray-cast camera
//! measures the part of the blob nothing hides, and does not see a wholly hidden target;
//! the projection camera does not see the target when its centre ray is blocked.

use eyehand::camera::{Camera, CameraModel, NotSeen, ProjectionCamera, RaycastCamera};
use eyehand::control::{FLOOR_GREYS, OBSTACLE_GREY};
use eyehand::experiment::show::{replay, RecordedRun};
use eyehand::experiment::{run, Config, ObstacleBox, RunOptions};
use eyehand::robot::{
    ArmModel, Controlled, DynamicSettings, DynamicSim, KinematicSim, Obstacle, Simulator,
};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

fn cameras() -> [Box<dyn Camera>; 2] {
    let model = CameraModel::default();
    [
        Box::new(ProjectionCamera::new(model)),
        Box::new(RaycastCamera::new(model, 256)),
    ]
}

/// A camera at `at` looking straight down (image x along world x).
fn looking_down(at: [f64; 3]) -> Isometry3<f64> {
    let down = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI);
    Isometry3::from_parts(Translation3::new(at[0], at[1], at[2]), down)
}

/// The kinematic arm at rest, with a 10 cm cube centred at (0.7 − `shift`, 0.3, 0.1).
fn world_with_cube(shift: f64) -> KinematicSim {
    let model = ArmModel::oscar6();
    let cube = Obstacle {
        centre: Point3::new(0.65 + shift, 0.3, 0.1),
        size: Vector3::repeat(0.1),
    };
    KinematicSim::new(model, DynamicSettings::default().moves).with_obstacles(vec![cube])
}

#[test]
fn a_target_behind_an_obstacle_is_not_seen_and_one_beside_it_is() {
    // The cube spans x 0.65–0.75, z 0.05–0.15, right under the camera, above the target.
    let sim = world_with_cube(0.05);
    let world = sim.world();
    let camera = looking_down([0.7, 0.3, 0.2]);
    let behind = Point3::new(0.7, 0.3, 0.0);
    for eye in cameras() {
        assert_eq!(eye.read_in(&camera, &behind, &world), Err(NotSeen::Hidden));
        assert!(eye.read(&camera, &behind).is_ok(), "seen without the cube");
    }
    // Beside the cube: the rays pass its edge (the cube enters the view's bounding box, so
    // the ray-cast camera tests every ray), and the reading is the scene-free one exactly.
    let camera = looking_down([0.74, 0.3, 0.2]);
    let beside = Point3::new(0.84, 0.3, 0.0);
    for eye in cameras() {
        let free = eye.read(&camera, &beside).unwrap();
        assert_eq!(eye.read_in(&camera, &beside, &world), Ok(free));
    }
}

#[test]
fn a_partly_hidden_target_gives_the_centroid_of_its_visible_part() {
    // The cube's face at x = 0.701, its top 5 cm under the camera, hides the rays to the
    // sphere (0.68–0.72) up to x ≈ 0.704: more than half of it.
    let sim = world_with_cube(0.001);
    let world = sim.world();
    let camera = looking_down([0.7, 0.3, 0.2]);
    let target = Point3::new(0.7, 0.3, 0.0);
    let model = CameraModel::default();
    let [projection, raycast] = cameras();
    // The centre ray is blocked: the projection camera does not see it.
    assert_eq!(
        projection.read_in(&camera, &target, &world),
        Err(NotSeen::Hidden)
    );
    let whole = raycast.read(&camera, &target).unwrap();
    let part = raycast.read_in(&camera, &target, &world).unwrap();
    let share = model.area_from_cz(part.z) / model.area_from_cz(whole.z);
    assert!(share > 0.3 && share < 0.5, "visible share {share}");
    // The visible part lies at image x > 0 (world x > 0.704): its centroid moved there.
    assert!(part.x > 8.0 && part.y.abs() < 0.05, "{part} vs {whole}");
}

/// The arm at the zero pose: the upper arm lies along x at z = 0.55 m (radius 8 cm).
fn arm_worlds() -> (KinematicSim, DynamicSim) {
    let model = ArmModel::oscar6();
    let settings = DynamicSettings::default();
    let mut kinematic = KinematicSim::new(model.clone(), settings.moves);
    let mut dynamic = DynamicSim::new(model, settings);
    kinematic.place(&Controlled::zeros()).unwrap();
    dynamic.place(&Controlled::zeros()).unwrap();
    (kinematic, dynamic)
}

#[test]
fn the_arms_own_link_hides_the_target_in_both_simulators() {
    let (kinematic, dynamic) = arm_worlds();
    // A camera under the upper arm looking up at a target above it.
    let up = Isometry3::translation(0.3, 0.0, 0.2);
    let above = Point3::new(0.3, 0.0, 0.9);
    let aside = Point3::new(0.3, 0.3, 0.9);
    for world in [kinematic.world(), dynamic.world()] {
        for eye in cameras() {
            assert_eq!(eye.read_in(&up, &above, &world), Err(NotSeen::Hidden));
            let free = eye.read(&up, &aside).unwrap();
            assert_eq!(eye.read_in(&up, &aside, &world), Ok(free));
        }
    }
}

#[test]
fn the_floor_and_obstacles_show_in_the_image() {
    let sim = world_with_cube(0.0);
    let world = sim.world();
    let camera = RaycastCamera::new(CameraModel::default(), 64);
    // From 15 cm above the cube's top, looking down: the cube in the middle, the floor
    // around it in tiles of both greys.
    let image = camera.render_scene(&looking_down([0.65, 0.3, 0.3]), &world);
    let count = |grey: u8| image.iter().filter(|&&g| g == Some(grey)).count();
    assert_eq!(image[32 * 64 + 32], Some(OBSTACLE_GREY));
    assert!(count(OBSTACLE_GREY) > 300, "{}", count(OBSTACLE_GREY));
    assert!(count(FLOOR_GREYS[0]) > 200 && count(FLOOR_GREYS[1]) > 200);
    assert_eq!(
        count(OBSTACLE_GREY) + count(FLOOR_GREYS[0]) + count(FLOOR_GREYS[1]),
        64 * 64
    );
}

#[test]
fn a_run_among_obstacles_reports_them_and_draws_no_target_inside_one() {
    let data = tempfile::tempdir().unwrap();
    let mut config = Config::default_config();
    config.trials = 150;
    config.camera = eyehand::experiment::CameraKind::Raycast;
    config.raycast_resolution = 64;
    // A 30 cm block across the middle of the reach space, from the floor up.
    config
        .assign("obstacle", "70,0,-12,30,40,20")
        .expect("a box");
    config.check().expect("a valid config");
    let result = run(&RunOptions::new(config.clone(), data.path())).unwrap();
    assert_eq!(
        result.summary.obstacles,
        vec![[70.0, 0.0, -12.0, 30.0, 40.0, 20.0]]
    );
    let info = std::fs::read_to_string(result.folder.join("info")).unwrap();
    assert!(info
        .lines()
        .any(|l| l.starts_with("obstacle 70.0,0.0,-12.0,30.0,40.0,20.0 ")));
    // The info file reads back with the obstacle (as `eyehand show` reads it), and the
    // replayed trials' targets all lie outside the block.
    let recorded = RecordedRun::read(&result.folder).unwrap();
    assert_eq!(recorded.setup.config.obstacle, config.obstacle);
    let block = ObstacleBox::obstacle(&config.obstacle[0]);
    let (mut targets, mut near) = (0, 0);
    replay(
        &recorded,
        150,
        |_| true,
        false,
        data.path(),
        |trace| {
            if let Some(look) = trace.looks.first() {
                targets += 1;
                assert!(!block.overlaps_ball(&look.object, 0.02), "{}", look.object);
                near += usize::from(block.overlaps_ball(&look.object, 0.1));
            }
            Ok(())
        },
    )
    .unwrap();
    assert!(
        targets > 140 && near > 5,
        "{targets} targets, {near} near the block"
    );
}
