//! Tangential stiffness of the Storåkers contact (Rojek 2016 eq 21, after Olsson &
//! Larsson 2013): the incremental law of eq 11 (`incremental.rs`) with
//!
//!   k_t = β k_n
//!
//! where k_n is the current tangent stiffness of the normal law (eq 22 while
//! loading plastically, eq 20 while unloading) and β = 0.5–5 per Olsson & Larsson.
//! Used with any normal law, it ties the tangential spring to that law's stiffness.
//! History: the tangential force vector (N). Stiffness for the time step: β k_n.

pub fn storakers_tangential_stiffness(beta: f64, normal_stiffness: f64) -> f64 {
    beta * normal_stiffness
}
