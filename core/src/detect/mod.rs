//! Broad phase: which pairs may be in contact. A Verlet neighbour list with a skin
//! is built by one of the detectors and reused until some particle has moved more
//! than half the skin, so the detector runs rarely. The list is sorted (i < j,
//! lexicographic), which makes iteration order — and so every result — independent
//! of the detector and of hashing.

pub mod brute;
pub mod cells;
mod grid;
pub mod locality;
pub mod multigrid;

use crate::contact::states::StateStore;
use crate::particles::Vec3;
use crate::space::Space;
use serde::{Deserialize, Serialize};

/// Broad-phase algorithm that finds the neighbour list's candidate pairs; all give the
/// same sorted list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Detector {
    /// Every pair tested, O(N²): the reference.
    Brute,
    /// Linked cells of edge ≥ 2 R_max + margin.
    Cells,
    /// One cell grid per size class (He, Dong & Zhou 2007), for wide size distributions.
    Multigrid,
}

impl Detector {
    /// All pairs (i < j) whose surfaces are closer than `margin` (m) through the nearest
    /// periodic image, in lexicographic order.
    pub fn candidate_pairs(
        &self,
        position: &[Vec3],
        radius: &[f64],
        margin: f64,
        space: &Space,
    ) -> Vec<(u32, u32)> {
        match self {
            Detector::Brute => brute::candidate_pairs(position, radius, margin, space),
            Detector::Cells => cells::candidate_pairs_in(position, radius, margin, space),
            Detector::Multigrid => multigrid::candidate_pairs(position, radius, margin, space),
        }
    }
}

/// How a run finds its candidate pairs: the detector, the Verlet skin, the law's
/// reach beyond touching, and the domain. Fixed for the run (part of its model).
#[derive(Clone, Debug)]
pub struct Detection {
    /// Algorithm that builds the list.
    pub detector: Detector,
    /// Verlet skin, m: the extra range that lets the list be reused until some particle
    /// has moved skin/2.
    pub skin: f64,
    /// Range beyond touching at which the contact law still acts, m.
    pub reach: f64,
    /// Domain with its periodic axes, for nearest-image distances.
    pub space: Space,
}

/// Candidate pairs, found within touching + `reach` (the range of cohesion) + `skin`,
/// and the positions and radii they were found at (part of a run's state). A rebuild
/// hands the old and new lists to the contacts' state store, which carries each
/// pair's state over by merging the two sorted lists.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct NeighborList {
    /// Candidate pairs of particle indices (i < j), sorted lexicographically.
    pub pairs: Vec<(u32, u32)>,
    /// Positions at the last build, m.
    pub reference_position: Vec<Vec3>,
    /// Radii at the last build, m.
    pub reference_radius: Vec<f64>,
    /// Number of builds so far.
    pub builds: u64,
}

impl NeighborList {
    /// Rebuild when there is no reference yet or some particle's displacement plus
    /// radius growth since the last build exceeds skin/2: then no pair outside the
    /// list can have come within reach (|Δx_i| + Δr_i ≤ skin/2 for both partners).
    pub fn update(
        &mut self,
        detection: &Detection,
        position: &[Vec3],
        radius: &[f64],
        states: &mut dyn StateStore,
    ) {
        let half_skin = 0.5 * detection.skin;
        let n = position.len();
        let stale = self.reference_position.len() != n || {
            // Slices of one length n (one bounds check per index) and the
            // nearest-image rule unpacked once (`MinimumImage`).
            let image = detection.space.minimum_image();
            let (reference_position, reference_radius, radius) = (
                &self.reference_position[..n],
                &self.reference_radius[..n],
                &radius[..n],
            );
            (0..n).any(|i| {
                // What radius growth leaves of the skin for motion; squared distances
                // keep the check free of square roots when nothing grows.
                let budget = half_skin - (radius[i] - reference_radius[i]).max(0.0);
                budget < 0.0
                    || image
                        .displacement(&position[i], &reference_position[i])
                        .norm_squared()
                        > budget * budget
            })
        };
        if stale {
            self.rebuild(detection, position, radius, states);
        }
    }

    /// Build the list now from the current positions and radii, and hand the old and
    /// new pair lists to `states` so each surviving pair keeps its contact history.
    pub fn rebuild(
        &mut self,
        detection: &Detection,
        position: &[Vec3],
        radius: &[f64],
        states: &mut dyn StateStore,
    ) {
        let Detection {
            detector,
            skin,
            reach,
            space,
        } = detection;
        let pairs = detector.candidate_pairs(position, radius, skin + reach, space);
        states.carry_pairs(&self.pairs, &pairs);
        self.pairs = pairs;
        self.reference_position = position.to_vec();
        self.reference_radius = radius.to_vec();
        self.builds += 1;
    }
}
