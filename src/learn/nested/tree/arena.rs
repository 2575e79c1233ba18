//! The tree's nodes in one arena: a `Vec` of nodes linked by `u32` indices, and the slots
//! of released nodes, reused first.

use super::Node;
use std::ops::{Deref, DerefMut};

/// Every node the tree ever made and did not release, by index; released slots wait in a
/// free list. A released node is unlinked from its parent and keeps no children the tree
/// can reach, so any index reached from the root is a live node.
#[derive(Debug)]
pub(crate) struct NodeArena<A, const N: usize> {
    nodes: Vec<Node<A, N>>,
    free: Vec<u32>,
}

impl<A, const N: usize> NodeArena<A, N> {
    /// An empty arena.
    pub(crate) fn new() -> Self {
        NodeArena {
            nodes: Vec::new(),
            free: Vec::new(),
        }
    }

    /// Forgets every node; `root` becomes node 0.
    pub(crate) fn replant(&mut self, root: Node<A, N>) {
        self.nodes.clear();
        self.free.clear();
        self.nodes.push(root);
    }

    /// Stores `node` in a free slot or a new one, and returns its index.
    pub(crate) fn insert(&mut self, node: Node<A, N>) -> u32 {
        match self.free.pop() {
            Some(id) => {
                self.nodes[id as usize] = node;
                id
            }
            None => {
                self.nodes.push(node);
                (self.nodes.len() - 1) as u32
            }
        }
    }

    /// Takes node `id`, already unlinked, out of use.
    pub(crate) fn release(&mut self, id: u32) {
        self.nodes[id as usize].fresh = 0;
        self.free.push(id);
    }
}

impl<A, const N: usize> Deref for NodeArena<A, N> {
    type Target = [Node<A, N>];

    fn deref(&self) -> &Self::Target {
        &self.nodes
    }
}

impl<A, const N: usize> DerefMut for NodeArena<A, N> {
    fn deref_mut(&mut self) -> &mut Self::Target {
        &mut self.nodes
    }
}
