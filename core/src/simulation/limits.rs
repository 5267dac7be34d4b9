//! The safeguards that stop a run as unstable instead of letting it give a wrong
//! answer: bounds on overlap, energy gain and per-step motion.

/// Safeguards that stop a run as unstable: bounds on overlap, energy gain and
/// per-step motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StabilityLimits {
    /// Largest overlap allowed, as a fraction of the smaller radius of the contact.
    pub max_overlap_fraction: f64,
    /// Largest energy gain without external work, as a fraction of the energy scale.
    pub max_energy_growth: f64,
    /// Steps between energy checks.
    pub check_every: u64,
    /// Largest move of a particle in one step, as a fraction of the smallest radius.
    /// At 0.25, two particles approaching each other close by at most half that
    /// radius per step, so a contact is seen at an overlap the default overlap limit
    /// (0.5) still accepts, instead of being stepped over.
    pub max_step_fraction: f64,
}

impl Default for StabilityLimits {
    fn default() -> Self {
        StabilityLimits {
            max_overlap_fraction: 0.5,
            max_energy_growth: 0.5,
            check_every: 100,
            max_step_fraction: 0.25,
        }
    }
}
