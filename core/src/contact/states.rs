//! Where the contacts of one run keep their state between steps.
//!
//! `ContactStates<S>` holds one `S` per neighbour-list pair and one per touched wall
//! facet, `S` the state type of the scene's laws (`model::StateOf`). The run holds
//! it behind `dyn StateStore`, so the simulation, the neighbour list and checkpoints
//! need not name the laws; the force loop, which does, takes it back as its own type
//! once per step.

use crate::contact::model::ContactState;
use crate::particles::Vec3;
use serde::{Deserialize, Serialize};
use std::any::Any;
use std::fmt::Debug;

/// The state of every contact of one run, `S` being the state type of the scene's laws.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ContactStates<S> {
    /// One per neighbour-list pair, in the list's order; empty when `S` is empty.
    pub pairs: Vec<S>,
    /// `[boundary][particle]` → (facet, state) for each facet touched; empty when
    /// `S` is empty.
    pub walls: Vec<Vec<Vec<(u32, S)>>>,
}

impl<S: ContactState> ContactStates<S> {
    /// Whether `S` holds anything (a frictionless elastic law keeps nothing).
    pub const KEPT: bool = std::mem::size_of::<S>() > 0;

    /// No contact yet, for `particles` particles and `boundaries` walls.
    pub fn new(particles: usize, boundaries: usize) -> Self {
        ContactStates {
            pairs: Vec::new(),
            walls: if Self::KEPT {
                vec![vec![Vec::new(); particles]; boundaries]
            } else {
                Vec::new()
            },
        }
    }

    /// The state of pair `k` (a fresh one when nothing is kept).
    pub fn pair(&self, k: usize) -> S {
        self.pairs.get(k).copied().unwrap_or_default()
    }

    /// The state of particle `i`'s contact with facet `facet` of wall `w`.
    pub fn wall(&self, w: usize, i: usize, facet: u32) -> S {
        self.walls
            .get(w)
            .and_then(|h| h.get(i))
            .and_then(|list| list.iter().find(|(f, _)| *f == facet))
            .map_or_else(S::default, |(_, s)| *s)
    }
}

/// A `ContactStates<S>` whose `S` only the force loop knows.
pub trait StateStore: Debug + Send + Sync {
    /// The concrete store, for the force loop to take back as its own type.
    fn as_any(&self) -> &dyn Any;
    /// The concrete store, mutable.
    fn as_any_mut(&mut self) -> &mut dyn Any;
    /// A boxed copy of the store.
    fn clone_box(&self) -> Box<dyn StateStore>;
    /// Whether the law keeps anything per contact.
    fn is_kept(&self) -> bool;
    /// Carry the pair states over a neighbour-list rebuild from `old` to `new` (both
    /// sorted): a pair in both keeps its state, a new pair starts fresh.
    fn carry_pairs(&mut self, old: &[(u32, u32)], new: &[(u32, u32)]);
    /// Room for one more particle's wall contacts.
    fn add_particle(&mut self);
    /// The tangential vector of pair `k`'s state (`None` when nothing is kept).
    fn pair_tangential(&self, k: usize) -> Option<Vec3>;
    /// Whether the store fits `pairs` pairs, `particles` particles and `boundaries` walls.
    fn fits(&self, pairs: usize, particles: usize, boundaries: usize) -> bool;
    /// The store as JSON, for checkpoints.
    fn to_json(&self) -> serde_json::Value;
    /// Replace the contents by a store written by `to_json` for the same laws.
    fn load_json(&mut self, value: serde_json::Value) -> Result<(), String>;
}

impl Clone for Box<dyn StateStore> {
    fn clone(&self) -> Self {
        self.clone_box()
    }
}

impl<S: ContactState> StateStore for ContactStates<S> {
    fn as_any(&self) -> &dyn Any {
        self
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }

    fn clone_box(&self) -> Box<dyn StateStore> {
        Box::new(self.clone())
    }

    fn is_kept(&self) -> bool {
        Self::KEPT
    }

    fn carry_pairs(&mut self, old: &[(u32, u32)], new: &[(u32, u32)]) {
        if !Self::KEPT {
            return;
        }
        let mut states = vec![S::default(); new.len()];
        let mut k_old = 0;
        for (k, pair) in new.iter().enumerate() {
            while k_old < old.len() && old[k_old] < *pair {
                k_old += 1;
            }
            if k_old < old.len() && old[k_old] == *pair {
                states[k] = self.pairs[k_old];
            }
        }
        self.pairs = states;
    }

    fn add_particle(&mut self) {
        for wall in &mut self.walls {
            wall.push(Vec::new());
        }
    }

    fn pair_tangential(&self, k: usize) -> Option<Vec3> {
        self.pairs.get(k).map(|s| s.tangential())
    }

    fn fits(&self, pairs: usize, particles: usize, boundaries: usize) -> bool {
        if Self::KEPT {
            self.pairs.len() == pairs
                && self.walls.len() == boundaries
                && self.walls.iter().all(|w| w.len() == particles)
        } else {
            self.pairs.is_empty() && self.walls.is_empty()
        }
    }

    fn to_json(&self) -> serde_json::Value {
        serde_json::to_value(self).expect("contact states are plain numbers")
    }

    fn load_json(&mut self, value: serde_json::Value) -> Result<(), String> {
        *self = serde_json::from_value(value).map_err(|e| e.to_string())?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rebuild_keeps_the_state_of_pairs_in_both_lists() {
        let mut s = ContactStates::<Vec3> {
            pairs: vec![Vec3::x(), Vec3::y(), Vec3::z()],
            walls: Vec::new(),
        };
        s.carry_pairs(&[(0, 1), (0, 2), (1, 2)], &[(0, 2), (0, 3), (1, 2)]);
        assert_eq!(s.pairs, vec![Vec3::y(), Vec3::zeros(), Vec3::z()]);
    }

    #[test]
    fn an_empty_state_stores_nothing() {
        let mut s = ContactStates::<()>::new(10, 2);
        s.carry_pairs(&[], &[(0, 1)]);
        assert!(s.pairs.is_empty() && s.walls.is_empty() && s.fits(5, 10, 2));
    }
}
