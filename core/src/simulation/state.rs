//! A run's state: everything the step changes — the particles, the clock and step,
//! the neighbour pairs with their contacts' history, where each wall is and the force
//! on it, the energy book, the largest overlap seen, a growth stage's final radii and
//! how far each pouring source has got. It is plain data: a checkpoint is this state
//! serialised beside the scene's hash (`checkpoint`), and resuming a run is putting
//! it back into a simulation built from the same scene (`Simulation::resume`).
//!
//! Why a restored run is bit-exact:
//! - every double is written as the shortest decimal that reads back to it (serde_json
//!   formats with ryu) and read with serde_json's `float_roundtrip` parser, which
//!   rounds correctly; the default, faster parser can be one ulp off;
//! - nothing is recomputed on restore, so no rounding can differ (the one cache a
//!   contact state holds, Storåkers' C, K and δ_res, is not stored: it is derived
//!   again from the stored δ_max by the same expressions);
//! - the particles' forces and torques are stored, since the next step's first half
//!   kick uses them rather than evaluating them again;
//! - the neighbour list keeps the positions and radii it was built at, so it is
//!   rebuilt at the same steps, and its sorted pairs sum the contact forces in the
//!   same order;
//! - a source's ChaCha generator is stored as its abstract state (seed, stream, word
//!   position), which continues the same stream of draws.
//!
//! JSON has no infinities or NaN; a run stops as unstable before one reaches the state.

use super::energy::EnergyBook;
use crate::boundary::WallPose;
use crate::contact::mdr::MdrParticles;
use crate::contact::model::ContactState;
use crate::contact::states::{ContactStates, StateStore};
use crate::detect::NeighborList;
use crate::generate::pour::SourceState;
use crate::particles::{Particles, Vec3};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// What the step changes (see the module documentation).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct State {
    /// The particles' arrays (position, velocity, spin, force, …).
    pub particles: Particles,
    /// Simulated time t, s.
    pub time: f64,
    /// Steps taken so far.
    pub step: u64,
    /// Time step Δt, s: set through `Simulation::set_time_step`, which checks it.
    pub(crate) dt: f64,
    /// Verlet neighbour list: the candidate pairs and where they were found.
    pub neighbors: NeighborList,
    /// What each pair and wall contact keeps between steps, in the shape of the
    /// scene's laws (`contact::states`).
    pub(crate) contacts: Contacts,
    /// Where each wall is and how fast it moves, in the model's wall order.
    pub walls: Vec<WallPose>,
    /// Force the particles exert on each wall at the current step, N.
    pub wall_force: Vec<Vec3>,
    /// The energy book: work of gravity and prescribed bodies, and E_mech at its start.
    pub energy: EnergyBook,
    /// Largest overlap / smaller radius seen so far.
    pub max_overlap_ratio: f64,
    /// Per particle, the final radius R_i a growth stage grows to, m (empty without one).
    pub target_radius: Vec<f64>,
    /// How far each pouring source has got, in the model's source order.
    pub sources: Vec<SourceState>,
    /// What the MDR law keeps per particle (apparent radius, free surface, volumes);
    /// `None` for every other law.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mdr: Option<MdrParticles>,
}

impl State {
    /// The radius of each particle's material, 4/3 π r³ = m / ρ: the particle's radius,
    /// except under MDR, whose apparent radius grows as plastic flow moves material out
    /// of the contact flats (the particle's volume is conserved, Zunker & Kamrin 2024
    /// Part I), so its material keeps the initial radius. Relative densities are taken
    /// with it, as mass fractions.
    pub fn material_radius(&self) -> &[f64] {
        match &self.mdr {
            Some(mdr) => &mdr.initial_radius[..self.particles.len()],
            None => &self.particles.radius,
        }
    }

    /// Particles the sources have still to pour.
    pub fn still_to_pour(&self) -> usize {
        self.sources.iter().map(|s| s.remaining).sum()
    }
}

/// The contact states of a run. The step holds them typed by the scene's laws,
/// behind `dyn StateStore`; a state read from JSON holds them as JSON until
/// `Simulation::resume` gives them the type of the model's laws, since a file cannot
/// name a Rust type.
#[derive(Clone, Debug)]
pub(crate) enum Contacts {
    /// Typed by the model's laws: what the step uses.
    Typed(Box<dyn StateStore>),
    /// As read from a checkpoint, not yet typed.
    Read(serde_json::Value),
}

impl Contacts {
    /// The typed store. A state read from JSON is typed by `Simulation::resume` before
    /// any step, query or capture can reach it.
    pub(crate) fn store(&self) -> &dyn StateStore {
        match self {
            Contacts::Typed(s) => &**s,
            Contacts::Read(_) => {
                panic!("contact states read from JSON are typed by Simulation::resume before use")
            }
        }
    }

    /// The typed store as the states of `S`, the scene's laws' (`StateOf<N, T>`).
    pub(crate) fn typed_mut<S: ContactState>(&mut self) -> &mut ContactStates<S> {
        self.store_mut()
            .as_any_mut()
            .downcast_mut::<ContactStates<S>>()
            .expect("the contact states were made for the scene's laws")
    }

    /// The typed store, mutable.
    pub(crate) fn store_mut(&mut self) -> &mut dyn StateStore {
        match self {
            Contacts::Typed(s) => &mut **s,
            Contacts::Read(_) => {
                panic!("contact states read from JSON are typed by Simulation::resume before use")
            }
        }
    }
}

impl Serialize for Contacts {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Contacts::Typed(s) => s.to_json().serialize(serializer),
            Contacts::Read(v) => v.serialize(serializer),
        }
    }
}

impl<'de> Deserialize<'de> for Contacts {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        serde_json::Value::deserialize(deserializer).map(Contacts::Read)
    }
}
