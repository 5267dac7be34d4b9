//! The composed contact law: normal ∘ damping ∘ tangential ∘ cohesion, only the roles
//! a scene enables. Geometry is computed once per contact (by the caller, for pairs and
//! walls alike) and passed read-only; the law returns forces and never applies them.
//!
//! Sign convention for every law: `normal` points from the partner (particle j or
//! the wall) to particle i; overlap δ = R_i + R_j − |x_i − x_j| > 0 in contact
//! (Rojek's h = −δ); a positive normal force pushes i away from the partner.
//!
//! How to add a law (a normal law; a tangential law is alike, in `tangential/`):
//! 1. Its file, `normal/<law>.rs`: a header with the equations and the source, then a
//!    type holding the law's parameters, deserialised from the scene as they are
//!    (`#[serde(deny_unknown_fields)]`), that implements `model::NormalModel`:
//!    - `name`, its `law` in the scene file;
//!    - `needs` (elastic constants, Hollomon constants, rotation), `check` (the rules
//!      of its parameters, reported as `contact.normal.<field>: rule, got value`) and
//!      `liggghts` (its LIGGGHTS model, if LIGGGHTS has it);
//!    - `examples`: closed forms written from the source's formulas, at the
//!      reference contact of `registry.rs` (at least one, or a test fails);
//!    - the force and tangent stiffness, time-step stiffness, recoverable energy and
//!      impact stiffness, with `type State` what one contact must remember (`()` for
//!      nothing; a state type of its own derives serde and implements
//!      `model::ContactState`);
//!    - its unit tests.
//! 2. Its registry entries in `normal/mod.rs` (the `NormalLaw` variant and the
//!    `each_normal!` arm, exhaustive matches: the compiler lists what is missing) and
//!    one line in `registry::normal_examples`. A tangential law also joins the family
//!    of its state type in `tangential/families.rs` (the `family!` list and its
//!    `each_family!` arm), or a new family if its state is of a new shape. The scene
//!    schema, validation, the force loop, the stored energy, the critical time step,
//!    checkpoints, tests/contact_laws.rs, tests/properties.rs, the contact-law bench
//!    and `tamp study stable-alpha` take the law from there.
//! 3. A page in docs/models/ and a verification case (`verification/`,
//!    docs/verification-notes.md) against a closed form or a peer code.

pub mod damping;
pub mod lammps;
pub mod lever_arm;
pub mod mdr;
pub mod model;
pub mod normal;
pub mod record;
pub mod registry;
pub mod rolling;
pub mod states;
pub mod tangential;
pub mod van_der_waals;

use crate::each_family;
use crate::material::PairProperties;
use crate::particles::Vec3;
use damping::Damping;
use model::{Composed, LawVisitor, NoFriction, NormalModel, Roles, TangentialModel};
use normal::NormalLaw;
use tangential::TangentialLaw;
use tangential::families::Spring;
use van_der_waals::Cohesion;

/// Geometry of one contact, computed once and shared by all roles.
#[derive(Clone, Copy, Debug)]
pub struct ContactGeometry {
    /// Unit normal n pointing from the partner (particle j or the wall) to particle i.
    pub normal: Vec3,
    /// δ > 0 in contact; −δ is the surface gap when apart (cohesion acts across it).
    pub overlap: f64,
    /// Effective radius R* of the pair, m (R_i against a plane wall; a curved wall
    /// gives its own).
    pub effective_radius: f64,
    /// Effective mass m* of the pair, kg (m_i against a wall or a prescribed particle).
    pub effective_mass: f64,
    /// Velocity of i's contact point relative to the partner's (includes spin when rotation is on).
    pub relative_velocity: Vec3,
}

impl ContactGeometry {
    /// dδ/dt: positive while the bodies approach.
    #[inline]
    pub fn overlap_rate(&self) -> f64 {
        -self.relative_velocity.dot(&self.normal)
    }

    /// Tangential part v_t = v_r − (v_r · n) n of the relative contact-point velocity, m/s.
    #[inline]
    pub fn tangential_velocity(&self) -> Vec3 {
        self.relative_velocity - self.normal * self.normal.dot(&self.relative_velocity)
    }
}

/// Force on particle i (the partner receives the opposite).
#[derive(Clone, Copy, Debug, Default)]
pub struct ContactForce {
    /// Total normal force along `normal` (elastic + damping − cohesion), N.
    pub normal: f64,
    /// Tangential (friction) force on i, perpendicular to `normal`, N.
    pub tangential: Vec3,
    /// Rolling resistance F_r on i (its torque R* n × F_r), N; zero without a
    /// rolling law.
    pub rolling: Vec3,
}

/// The scene's law: one value per role, as the scene file gives them, turned into
/// its `Composed` type once per run by `visit`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactLaw {
    /// The normal law (always present).
    pub normal: NormalLaw,
    /// The normal dashpot, if the scene has one.
    pub damping: Option<Damping>,
    /// The friction law; `None` for frictionless contacts.
    pub tangential: Option<TangentialLaw>,
    /// The attraction across small gaps, if any.
    pub cohesion: Option<Cohesion>,
    /// The rolling resistance, if any; it joins the tangential law (`rolling/mod.rs`).
    pub rolling: Option<rolling::RollingLaw>,
    /// Where the contact acts on spinning spheres (`contact.lever_arm`).
    pub lever_arm: lever_arm::LeverArm,
    /// Whether the elastic plus damping normal force is clamped at zero
    /// (`contact.damping.limit`).
    pub no_pull: bool,
}

impl ContactLaw {
    /// The roles assembled, each law given what it takes from the others
    /// (`TangentialModel::bind`).
    pub fn new(
        normal: NormalLaw,
        damping: Option<Damping>,
        tangential: Option<TangentialLaw>,
        cohesion: Option<Cohesion>,
    ) -> Self {
        let roles = Roles {
            normal: &normal,
            damping: damping.as_ref(),
        };
        let tangential = tangential.map(|mut t| {
            t.bind(roles);
            t
        });
        ContactLaw {
            normal,
            damping,
            tangential,
            cohesion,
            rolling: None,
            lever_arm: lever_arm::LeverArm::default(),
            no_pull: false,
        }
    }

    /// How far beyond touching the law acts (the cohesion cut-off), m.
    pub fn reach(&self) -> f64 {
        self.cohesion.map_or(0.0, |c| c.reach())
    }

    /// The forces of one contact driven along `path` (its geometry and the step at
    /// each evaluation), starting from a fresh state: one law's behaviour without a
    /// simulation around it, for tests and studies.
    pub fn forces_along(
        &self,
        pair: &PairProperties,
        path: &[(ContactGeometry, f64)],
    ) -> Vec<ContactForce> {
        struct Along<'a>(&'a PairProperties, &'a [(ContactGeometry, f64)]);
        impl LawVisitor for Along<'_> {
            type Output = Vec<ContactForce>;
            fn visit<N: NormalModel, T: TangentialModel>(
                self,
                law: Composed<N, T>,
            ) -> Vec<ContactForce> {
                let mut state = model::StateOf::<N, T>::default();
                self.1
                    .iter()
                    .map(|(g, dt)| law.evaluate(g, self.0, &mut state, *dt))
                    .collect()
            }
        }
        self.visit(Along(pair, path))
    }

    /// Run `visitor` with the scene's normal law and tangential family as types (one
    /// compiled visitor per combination; the other roles are values, model.rs).
    pub fn visit<V: LawVisitor>(&self, visitor: V) -> V::Output {
        // The library's unit-test build would compile every combination a second time
        // (docs/performance.md, "Compile time"): tests that build or run a simulation
        // are integration tests, which link the library built once.
        #[cfg(test)]
        {
            let _ = visitor;
            panic!(
                "a unit test reached ContactLaw::visit: tests that build a simulation belong in tests/ (docs/performance.md)"
            );
        }
        #[cfg(not(test))]
        crate::each_normal!(self.normal, n => self.with_tangential(n, visitor))
    }

    #[cfg_attr(test, allow(dead_code))]
    fn with_tangential<N: NormalModel, V: LawVisitor>(&self, n: N, v: V) -> V::Output {
        match (self.tangential, self.rolling) {
            (None, _) => self.compose(n, NoFriction, v),
            (Some(tangential), None) => each_family!(tangential, t => self.compose(n, t, v)),
            (Some(tangential), Some(rolling)) => {
                let sliding = Spring::of(tangential).unwrap_or_else(|| {
                    panic!(
                        "rolling resistance joins a tangential law that keeps one spring; the scene's rules refuse '{}' with it",
                        tangential.name()
                    )
                });
                self.compose(n, rolling::WithRolling { sliding, rolling }, v)
            }
        }
    }

    #[cfg_attr(test, allow(dead_code))]
    fn compose<N: NormalModel, T: TangentialModel, V: LawVisitor>(
        &self,
        normal: N,
        tangential: T,
        v: V,
    ) -> V::Output {
        v.visit(Composed {
            normal,
            damping: self.damping.and_then(|d| d.dashpot(&self.normal)),
            tangential,
            cohesion: self.cohesion,
            no_pull: self.no_pull,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::damping::{CriticalFraction, Dashpot};
    use crate::contact::model::StateOf;
    use crate::contact::normal::Hertz;
    use crate::contact::tangential::CundallStrack;

    type Law = Composed<Hertz, CundallStrack>;

    fn law() -> Law {
        Composed {
            normal: Hertz {},
            damping: Some(Dashpot::CriticalFraction(CriticalFraction { xi: 0.3 })),
            tangential: CundallStrack { stiffness: 1e5 },
            cohesion: None,
            no_pull: false,
        }
    }

    /// Parting fast at a small overlap, the dashpot outpulls the spring: the total
    /// normal force is negative, or zero with the clamp, and then no friction acts.
    #[test]
    fn the_clamp_keeps_the_normal_force_from_pulling() {
        let parting = |sign: f64| ContactGeometry {
            normal: Vec3::z(),
            overlap: 1e-9,
            effective_radius: 1e-3,
            effective_mass: 1e-3,
            relative_velocity: Vec3::new(0.05, 0.0, sign),
        };
        let free = [1.0, -1.0]
            .map(|s| law().evaluate(&parting(s), &pair(), &mut Default::default(), 1e-6));
        let k = free
            .iter()
            .position(|f| f.normal < 0.0)
            .expect("one way pulls");
        let clamped = Composed {
            no_pull: true,
            ..law()
        }
        .evaluate(
            &parting([1.0, -1.0][k]),
            &pair(),
            &mut Default::default(),
            1e-6,
        );
        assert_eq!(clamped.normal, 0.0);
        assert_eq!(clamped.tangential, Vec3::zeros());
        // Pushing (the other direction), the clamp changes nothing.
        let pushing = parting([1.0, -1.0][1 - k]);
        let with = Composed {
            no_pull: true,
            ..law()
        }
        .evaluate(&pushing, &pair(), &mut Default::default(), 1e-6);
        assert_eq!(
            (with.normal, with.tangential),
            (free[1 - k].normal, free[1 - k].tangential)
        );
    }

    fn pair() -> PairProperties {
        PairProperties {
            effective_modulus: Some(1e9),
            effective_shear_modulus: Some(4e8),
            hollomon: None,
            law_constant: None,
            friction: 0.5,
        }
    }

    #[test]
    fn swapping_bodies_reverses_force() {
        let g = ContactGeometry {
            normal: Vec3::new(0.0, 0.6, 0.8),
            overlap: 1e-5,
            effective_radius: 1e-3,
            effective_mass: 1e-3,
            relative_velocity: Vec3::new(0.1, -0.2, -0.05),
        };
        let swapped = ContactGeometry {
            normal: -g.normal,
            relative_velocity: -g.relative_velocity,
            ..g
        };
        let (mut s1, mut s2) = (
            StateOf::<Hertz, CundallStrack>::default(),
            StateOf::<Hertz, CundallStrack>::default(),
        );
        let f1 = law().evaluate(&g, &pair(), &mut s1, 1e-6);
        let f2 = law().evaluate(&swapped, &pair(), &mut s2, 1e-6);
        let total1 = g.normal * f1.normal + f1.tangential;
        let total2 = swapped.normal * f2.normal + f2.tangential;
        assert!((total1 + total2).norm() <= 1e-12 * total1.norm());
    }

    #[test]
    fn force_is_continuous_at_first_touch() {
        let g = ContactGeometry {
            normal: Vec3::z(),
            overlap: 1e-300,
            effective_radius: 1e-3,
            effective_mass: 1e-3,
            relative_velocity: Vec3::zeros(),
        };
        let f = law().evaluate(&g, &pair(), &mut Default::default(), 1e-6);
        assert!(f.normal.abs() < 1e-300 && f.tangential.norm() == 0.0);
    }

    /// The state a composed law keeps is what its laws keep: nothing for a
    /// frictionless Hertz contact, one 3-vector for a Cundall–Strack spring.
    #[test]
    fn contact_state_is_sized_to_the_laws() {
        assert_eq!(std::mem::size_of::<StateOf<Hertz, NoFriction>>(), 0);
        assert_eq!(std::mem::size_of::<StateOf<Hertz, CundallStrack>>(), 24);
        const { assert!(!Composed::<Hertz, NoFriction>::HAS_STATE) };
        const { assert!(Law::HAS_STATE) };
    }
}
