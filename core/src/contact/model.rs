//! The four roles of a contact law as traits, and their composition.
//!
//! Each law is one type implementing its role's trait (`NormalModel`,
//! `DampingModel`, `TangentialModel`, `CohesionModel`). `Composed<N, T>` evaluates the
//! four roles in their fixed order. The scene's `ContactLaw` (runtime enums) is turned
//! into its `Composed` type once per run by `ContactLaw::visit`. What is a type there is
//! what decides the loop's storage and most of its arithmetic: the normal law `N`, and
//! the tangential law's family `T` (tangential/families.rs), by the state a contact
//! keeps, with `NoFriction` for friction off, whose code compiles to nothing. The
//! damping kind, the law within a tangential family and cohesion are branches fixed for
//! the run (a `match` the processor predicts every time): as types they multiplied the
//! compiled loops by their number (docs/performance.md, "Compile time").
//!
//! What a contact remembers is typed by its laws (`ContactState`): the pair
//! `(N::State, T::State)`, zero bytes for a frictionless Hertz contact, one 3-vector
//! for a spring.

use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::damping::{Damping, Dashpot};
use crate::contact::lammps::{LammpsNormal, NoLammpsModel};
use crate::contact::mdr::contact::MdrForce;
use crate::contact::mdr::{Mdr, MdrContact};
use crate::contact::normal::NormalLaw;
use crate::contact::registry::{NormalExample, TangentialExample};
use crate::contact::rolling::RollingInput;
use crate::contact::states::ContactStates;
use crate::contact::van_der_waals::Cohesion;
use crate::contact::{ContactForce, ContactGeometry};
use crate::error::Errors;
use crate::material::PairProperties;
use crate::particles::Vec3;
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::fmt::Debug;

pub use crate::contact::tangential::TangentialInput;

/// What one contact keeps between steps for one law. Reset to `Default` when the
/// bodies separate.
pub trait ContactState:
    Copy + Default + Debug + PartialEq + Serialize + DeserializeOwned + Send + Sync + 'static
{
    /// The tangential spring or force vector the state holds (zero when none); for
    /// diagnostics that follow one contact.
    fn tangential(&self) -> Vec3 {
        Vec3::zeros()
    }
}

impl ContactState for () {}

/// A spring elongation (Cundall–Strack, LIGGGHTS's shear) or an incremental
/// tangential force (Mindlin no-slip, Storåkers), m or N.
impl ContactState for Vec3 {
    fn tangential(&self) -> Vec3 {
        *self
    }
}

/// The state of a composed contact: the normal law's, then the tangential law's.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Composite<N, T> {
    /// The normal law's state.
    pub normal: N,
    /// The tangential law's state.
    pub tangential: T,
}

impl<N: ContactState, T: ContactState> ContactState for Composite<N, T> {
    fn tangential(&self) -> Vec3 {
        self.tangential.tangential()
    }
}

/// What a law reads from the materials and the scene besides its own parameters;
/// validation asks the scene for it.
#[derive(Clone, Copy, Debug, Default)]
pub struct Needs {
    /// E and ν of every material; the text (possibly empty) says what for.
    pub elastic: Option<&'static str>,
    /// Hollomon constants of every particle material, with one exponent for all.
    pub hollomon: bool,
    /// Particle spins; the text is the rule a scene without `rotation` breaks.
    pub rotation: Option<&'static str>,
}

/// A law's entry in a LIGGGHTS 3.8 deck (`tamp export-liggghts`): the words of
/// `pair_style gran model <model> tangential history <options>` and the `fix
/// property/global` lines the model reads besides youngsModulus and poissonsRatio,
/// in the order the deck writes them.
#[derive(Clone, Debug, PartialEq)]
pub struct LiggghtsDeck {
    /// The word after `model` (`hertz`, `hooke`).
    pub model: &'static str,
    /// Words after the tangential model, or "".
    pub options: &'static str,
    /// The `fix property/global` lines, in deck order.
    pub properties: Vec<LiggghtsProperty>,
}

/// One `fix property/global <name> <values>` line.
#[derive(Clone, Debug, PartialEq)]
pub struct LiggghtsProperty {
    /// LIGGGHTS's property name, e.g. `coefficientFriction`.
    pub name: &'static str,
    /// The property's style and values.
    pub values: LiggghtsValues,
}

/// The values of a property, by LIGGGHTS style.
#[derive(Clone, Debug, PartialEq)]
pub enum LiggghtsValues {
    /// `scalar v`.
    Scalar(f64),
    /// `peratomtype v_1 … v_n`, one per atom type (tamp material).
    PerType(Vec<f64>),
    /// `peratomtypepair n v_11 v_12 … v_nn`, row-major.
    PerTypePair(Vec<f64>),
}

/// A field the deck cannot express: (scene path, reason).
pub type LiggghtsRefusal = (String, String);

/// One kind of contact in the scene (`export-liggghts` lists every pair of particle
/// classes and every class against every wall).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LiggghtsContact {
    /// Effective mass m* of the contact, kg.
    pub effective_mass: f64,
    /// Effective radius R* of the contact, m.
    pub effective_radius: f64,
    /// Effective modulus E* of the contact, Pa.
    pub effective_modulus: f64,
    /// Atom type index (tamp material index) and radius of each particle LIGGGHTS may
    /// take as "i": both for a pair, the particle alone for a wall (`None`).
    pub first: (usize, f64),
    /// The second particle's atom type and radius, m; `None` for a wall contact.
    pub second: Option<(usize, f64)>,
}

/// What a law's deck entry reads from the scene.
#[derive(Clone, Debug)]
pub struct LiggghtsScene<'a> {
    /// The scene's damping role, if any.
    pub damping: Option<&'a Damping>,
    /// Whether the scene has a tangential law.
    pub tangential: bool,
    /// Number of atom types (tamp materials).
    pub types: usize,
    /// μ of every pair of atom types, row-major (zeros without a tangential law).
    pub friction: Vec<f64>,
    /// LIGGGHTS's `coefficientRestitution` for the scene's damping (1 without
    /// damping); `None` for a constant γ_n, or when no e expresses it (refused).
    pub restitution: Option<f64>,
    /// The contact kinds; empty until the scene is built (a first pass, before the
    /// particles are placed, checks everything else).
    pub contacts: Vec<LiggghtsContact>,
}

impl LiggghtsScene<'_> {
    /// `coefficientFriction peratomtypepair`.
    pub fn coefficient_friction(&self) -> LiggghtsProperty {
        LiggghtsProperty {
            name: "coefficientFriction",
            values: LiggghtsValues::PerTypePair(self.friction.clone()),
        }
    }

    /// `coefficientRestitution peratomtypepair`, the same e for every pair.
    pub fn coefficient_restitution(&self) -> LiggghtsProperty {
        self.uniform_pair("coefficientRestitution", self.restitution.unwrap_or(1.0))
    }

    /// A `peratomtypepair` property with one value for every pair of types.
    pub fn uniform_pair(&self, name: &'static str, value: f64) -> LiggghtsProperty {
        LiggghtsProperty {
            name,
            values: LiggghtsValues::PerTypePair(vec![value; self.types * self.types]),
        }
    }
}

/// The other roles of the scene's law, for the rules that join two roles.
#[derive(Clone, Copy, Debug)]
pub struct Roles<'a> {
    /// The scene's normal law.
    pub normal: &'a NormalLaw,
    /// The scene's damping role, if any.
    pub damping: Option<&'a Damping>,
}

/// Normal force (without a separate damping role) and its tangent stiffness.
#[derive(Clone, Copy, Debug)]
pub struct NormalResponse {
    /// Normal force F_n on i along the normal, N (> 0 repulsive).
    pub force: f64,
    /// Tangent stiffness dF_n/dδ at this overlap, N/m.
    pub stiffness: f64,
}

/// The elastic, viscoelastic or plastic part of the normal force.
pub trait NormalModel: Copy + Debug + PartialEq {
    /// What one contact of this law remembers between steps (`()` for an elastic law).
    type State: ContactState;
    /// Whether the law dissipates by itself: a separate damping role is then
    /// refused.
    const OWN_DISSIPATION: bool = false;

    /// The `law` of the scene file, also the law's name in outputs.
    fn name(&self) -> &'static str;

    /// What the law reads from the materials.
    fn needs(&self) -> Needs {
        Needs::default()
    }

    /// The rules of its own parameters; `path` is where the scene holds them.
    fn check(&self, _path: &str, _errors: &mut Errors) {}

    /// The LIGGGHTS `model` whose restitution damping and `tangential history`
    /// tamp reproduces beside this law (`liggghts_restitution`, `liggghts_history`),
    /// if it is one of them.
    fn liggghts(&self) -> Option<LiggghtsModel> {
        None
    }

    /// Its model in LAMMPS's `pair granular` (`tamp export-lammps`,
    /// contact/lammps.rs), or why LAMMPS has none.
    fn lammps(&self) -> Result<LammpsNormal, NoLammpsModel> {
        Err(NoLammpsModel(format!(
            "pair granular has no normal model with the physics of '{}'",
            self.name()
        )))
    }

    /// Its model in a LIGGGHTS 3.8 deck for this scene (`tamp export-liggghts`),
    /// or the fields of the scene it cannot express; `None` when LIGGGHTS has no
    /// counterpart of the law.
    fn liggghts_deck(
        &self,
        _scene: &LiggghtsScene,
    ) -> Option<Result<LiggghtsDeck, Vec<LiggghtsRefusal>>> {
        None
    }

    /// Its closed forms (at least one; see `registry.rs`).
    fn examples() -> Vec<NormalExample>
    where
        Self: Sized;

    /// Force and stiffness at this step; advances the state of laws with memory.
    fn response(
        &self,
        overlap: f64,
        overlap_rate: f64,
        effective_radius: f64,
        pair: &PairProperties,
        state: &mut Self::State,
    ) -> NormalResponse;

    /// Tangent stiffness of a stored contact state, N/m.
    fn stiffness(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        state: &Self::State,
    ) -> f64;

    /// Stiffness the critical time step must resolve (Rojek §3.4); laws with an
    /// unloading branch stiffer than the loading one add it (see `walton_braun`).
    fn time_step_stiffness(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        state: &Self::State,
    ) -> f64 {
        self.stiffness(overlap, effective_radius, pair, state)
    }

    /// Energy the contact would give back on elastic unloading, J.
    fn energy(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        state: &Self::State,
    ) -> f64;

    /// Normal stiffness expected in a head-on impact at `speed` (for the critical
    /// time step before any contact exists), N/m.
    fn impact_stiffness(
        &self,
        effective_mass: f64,
        speed: f64,
        effective_radius: f64,
        pair: &PairProperties,
    ) -> f64;

    /// Whether `impact_stiffness` depends on the impact speed (the nonlinear laws):
    /// the time step then needs a characteristic velocity before contacts exist.
    fn stiffness_depends_on_speed(&self) -> bool;

    /// What the law derives from a material pair once, when the scene is built
    /// (`PairProperties::law_constant`), rather than at every contact.
    fn pair_constant(&self, _pair: &PairProperties) -> Option<f64> {
        None
    }

    /// The name in `accuracy::calibration::MODELS` of the error model calibrated for
    /// this law beside `damping`, or `None` where it has none (no impact closed form).
    fn error_model(&self, _damping: Option<&Damping>) -> Option<&'static str> {
        None
    }

    /// The MDR law, whose contacts need their particles' state (the force loop's
    /// per-particle pass, simulation/mdr_pass.rs); `None` for every pairwise law, for
    /// which that pass compiles to nothing.
    fn mdr(&self) -> Option<&Mdr> {
        None
    }

    /// MDR's contact history within a state of this law; `None` for the pairwise laws.
    fn mdr_contact(_state: &mut Self::State) -> Option<&mut MdrContact> {
        None
    }
}

/// A viscous normal dashpot c_n · dδ/dt.
pub trait DampingModel: Copy + Debug {
    /// The `kind` of the scene file.
    fn name(&self) -> &'static str;
    /// The rules of its own parameters; `path` is where the scene holds them.
    fn check(&self, _path: &str, _roles: Roles, _errors: &mut Errors) {}
    /// c_n of a contact with this effective mass and normal tangent stiffness;
    /// `contact_radius` gives a = √(δR*), evaluated only by the forms that need it.
    fn coefficient(
        &self,
        effective_mass: f64,
        stiffness: f64,
        contact_radius: impl FnOnce() -> f64,
    ) -> f64;
    /// Damping ratio ξ of a contact with this mass, stiffness and contact radius
    /// (Rojek eq 28).
    fn ratio(&self, effective_mass: f64, stiffness: f64, contact_radius: f64) -> f64;
}

/// The tangential force, limited by the contact's normal force.
pub trait TangentialModel: Copy + Debug + PartialEq {
    /// What one contact of this law remembers between steps (`()` when nothing).
    type State: ContactState;
    /// False for `NoFriction`: no tangential velocity, force or torque is computed.
    const ACTIVE: bool = true;
    /// True for a law with rolling resistance (`WithRolling`): the force loop then
    /// adds the rolling torque R* n × F_r to i and its opposite to j.
    const ROLLS: bool = false;

    /// The `law` of the scene file, also the law's name in outputs.
    fn name(&self) -> &'static str;

    /// What the law reads from the materials and the scene.
    fn needs(&self) -> Needs {
        Needs::default()
    }

    /// The rules of its own parameters, and of the other roles it works with;
    /// `path` is where the scene holds the law (`contact.tangential`).
    fn check(&self, _path: &str, _roles: Roles, _errors: &mut Errors) {}

    /// Its `tangential` model in LAMMPS's `pair granular` (`tamp export-lammps`): the
    /// words after `tangential`, with μ written as `{mu}`, or why LAMMPS has none. Only
    /// the `lammps_*` laws have one: tamp's other laws cap the force at μ·max(F_n, 0)
    /// where LAMMPS takes μ|F_n|, and have no dashpot following the normal damping
    /// (docs/lammps.md).
    fn lammps(&self) -> Result<String, NoLammpsModel> {
        Err(NoLammpsModel(format!(
            "'{}' is none of LAMMPS's tangential models (its Coulomb limit, history or dashpot differs from theirs); 'lammps_mindlin', 'lammps_linear_history' and 'lammps_linear_nohistory' reproduce LAMMPS's mindlin*, linear_history and linear_nohistory",
            self.name()
        )))
    }

    /// Take the parameters the law derives from the other roles (LIGGGHTS's
    /// `tangential history`); called once when the scene's law is assembled.
    fn bind(&mut self, _roles: Roles) {}

    /// Its closed forms (at least one; see `registry.rs`).
    fn examples() -> Vec<TangentialExample>
    where
        Self: Sized;

    /// Tangential force on particle i; advances the state.
    fn force(&self, input: &TangentialInput, state: &mut Self::State) -> Vec3;

    /// Rolling resistance F_r on particle i (`ROLLS` laws); advances the state.
    #[inline(always)]
    fn rolling(&self, _input: &RollingInput, _state: &mut Self::State) -> Vec3 {
        Vec3::zeros()
    }

    /// Largest tangent stiffness at this contact state (θ = 1), N/m; zero for the
    /// spring-less laws.
    fn stiffness(&self, input: &TangentialInput) -> f64;

    /// Energy held in the tangential state, J.
    fn energy(&self, input: &TangentialInput, state: &Self::State) -> f64;

    /// Tangential stiffness known before any contact exists, given the normal
    /// impact stiffness (a fixed spring k_s, or LIGGGHTS hooke's k_t = k_n), N/m.
    fn stiffness_before_contact(&self, _impact_stiffness: f64) -> f64 {
        0.0
    }

    /// γ_s of a viscous law, N·s/m: it adds an explicit stability limit.
    fn viscous_coefficient(&self) -> Option<f64> {
        None
    }

    /// x_γ,t of a law with LAMMPS's tangential dashpot γ_t = x_γ,t c_n (c_n the normal
    /// damping's coefficient of the contact), 0 without one: the dashpot damps the
    /// tangential mode, which shortens the critical time step.
    fn dashpot_over_normal(&self) -> f64 {
        0.0
    }
}

/// Friction off.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NoFriction;

impl TangentialModel for NoFriction {
    type State = ();
    const ACTIVE: bool = false;
    fn name(&self) -> &'static str {
        "none"
    }
    fn examples() -> Vec<TangentialExample> {
        Vec::new()
    }
    #[inline(always)]
    fn force(&self, _: &TangentialInput, _: &mut ()) -> Vec3 {
        Vec3::zeros()
    }
    fn stiffness(&self, _: &TangentialInput) -> f64 {
        0.0
    }
    fn energy(&self, _: &TangentialInput, _: &()) -> f64 {
        0.0
    }
}

/// An attraction acting across a gap up to `reach`.
pub trait CohesionModel: Copy + Debug {
    /// The rules of its own parameters; `path` is where the scene holds them.
    fn check(&self, _path: &str, _errors: &mut Errors) {}
    /// How far beyond touching it acts, m.
    fn reach(&self) -> f64;
    /// Attractive force magnitude at surface gap `gap` (negative = overlap), N.
    fn force(&self, gap: f64, effective_radius: f64) -> f64;
    /// Potential energy, J (≤ 0).
    fn energy(&self, gap: f64, effective_radius: f64) -> f64;
}

/// One law per role, evaluated as normal → damping → tangential → cohesion.
#[derive(Clone, Copy, Debug)]
pub struct Composed<N, T> {
    /// The normal law.
    pub normal: N,
    /// The normal dashpot, if any.
    pub damping: Option<Dashpot>,
    /// The friction law's family (`NoFriction` when off).
    pub tangential: T,
    /// The attraction, if any.
    pub cohesion: Option<Cohesion>,
    /// Whether the elastic plus damping normal force is clamped at zero: a branch
    /// fixed for the run, not a type, as it only compares one number.
    pub no_pull: bool,
}

/// The state a composed law keeps per contact.
pub type StateOf<N, T> = Composite<<N as NormalModel>::State, <T as TangentialModel>::State>;

impl<N: NormalModel, T: TangentialModel> Composed<N, T> {
    /// Whether contacts keep anything between steps.
    pub const HAS_STATE: bool = ContactStates::<StateOf<N, T>>::KEPT;

    /// How far beyond touching the law acts (the cohesion cut-off), m.
    #[inline(always)]
    pub fn reach(&self) -> f64 {
        self.cohesion.map_or(0.0, |c| c.reach())
    }

    #[inline(always)]
    fn tangential_input(
        g: &ContactGeometry,
        pair: &PairProperties,
        normal_force: f64,
        normal_stiffness: f64,
        normal_damping: f64,
        dt: f64,
    ) -> TangentialInput {
        TangentialInput {
            normal: g.normal,
            tangential_velocity: g.tangential_velocity(),
            dt,
            friction: pair.friction,
            normal_force,
            normal_stiffness,
            overlap: g.overlap,
            effective_radius: g.effective_radius,
            effective_shear_modulus: pair.effective_shear_modulus.unwrap_or(0.0),
            effective_mass: g.effective_mass,
            normal_damping,
        }
    }

    /// The tangential input of a stored contact state at rest (for energies and
    /// stiffnesses, which depend on the overlap but not on the motion).
    fn resting_input(
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        normal_stiffness: f64,
    ) -> TangentialInput {
        let g = ContactGeometry {
            normal: Vec3::z(),
            overlap,
            effective_radius,
            effective_mass: 0.0,
            relative_velocity: Vec3::zeros(),
        };
        Self::tangential_input(&g, pair, 0.0, normal_stiffness, 0.0, 0.0)
    }

    /// Evaluate the roles in their fixed order: normal, damping, tangential (limited
    /// by the contact's normal force), cohesion. The state is reset while the bodies
    /// are apart.
    #[inline(always)]
    pub fn evaluate(
        &self,
        g: &ContactGeometry,
        pair: &PairProperties,
        state: &mut StateOf<N, T>,
        dt: f64,
    ) -> ContactForce {
        self.evaluate_given(g, pair, state, dt, None, Vec3::zeros())
    }

    /// `evaluate` with the normal force `given` by the caller: MDR's, which the force
    /// loop computes with the contact's particles (its force without the dashpot, and
    /// the dashpot's coefficient). The dashpot, friction and cohesion follow as in
    /// `evaluate`; a law that resists rolling reads the relative spin ω_i − ω_j
    /// (`relative_spin`, ω_i against a wall) after the friction.
    #[inline(always)]
    pub fn evaluate_given(
        &self,
        g: &ContactGeometry,
        pair: &PairProperties,
        state: &mut StateOf<N, T>,
        dt: f64,
        given: Option<MdrForce>,
        relative_spin: Vec3,
    ) -> ContactForce {
        let mut force = ContactForce::default();
        if g.overlap > 0.0 {
            let rate = g.overlap_rate();
            let (stiffness, damping) = if let Some(m) = given {
                force.normal = m.force + m.damping * rate;
                let k = self
                    .normal
                    .stiffness(g.overlap, g.effective_radius, pair, &state.normal);
                (k, m.damping)
            } else {
                let elastic = self.normal.response(
                    g.overlap,
                    rate,
                    g.effective_radius,
                    pair,
                    &mut state.normal,
                );
                force.normal = elastic.force;
                let damping = if let Some(dashpot) = &self.damping {
                    let c = dashpot.coefficient(g.effective_mass, elastic.stiffness, || {
                        (g.overlap * g.effective_radius).sqrt()
                    });
                    force.normal += c * rate;
                    // LAMMPS's `limit_damping`, LIGGGHTS's `limitForce on`: the clamp
                    // comes before the friction law reads the normal force, as in both.
                    if self.no_pull && force.normal < 0.0 {
                        force.normal = 0.0;
                    }
                    c
                } else {
                    0.0
                };
                (elastic.stiffness, damping)
            };
            if T::ACTIVE {
                let input = Self::tangential_input(g, pair, force.normal, stiffness, damping, dt);
                force.tangential = self.tangential.force(&input, &mut state.tangential);
            }
            if T::ROLLS {
                let input = RollingInput {
                    normal: g.normal,
                    velocity: relative_spin.cross(&g.normal) * g.effective_radius,
                    dt,
                    normal_force: force.normal,
                };
                force.rolling = self.tangential.rolling(&input, &mut state.tangential);
            }
        } else if Self::HAS_STATE {
            *state = StateOf::<N, T>::default();
        }
        if let Some(cohesion) = &self.cohesion {
            force.normal -= cohesion.force(-g.overlap, g.effective_radius);
        }
        force
    }

    /// Energy stored in the contact (recoverable normal and tangential energy, and
    /// the cohesive potential), J.
    pub fn stored_energy(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        state: &StateOf<N, T>,
    ) -> f64 {
        let cohesion = self
            .cohesion
            .map_or(0.0, |c| c.energy(-overlap, effective_radius));
        if overlap <= 0.0 {
            return cohesion;
        }
        let normal = self
            .normal
            .energy(overlap, effective_radius, pair, &state.normal);
        let tangential = if T::ACTIVE {
            let k_n = self
                .normal
                .stiffness(overlap, effective_radius, pair, &state.normal);
            self.tangential.energy(
                &Self::resting_input(overlap, effective_radius, pair, k_n),
                &state.tangential,
            )
        } else {
            0.0
        };
        normal + tangential + cohesion
    }

    /// Largest tangent stiffness (normal, and tangential with θ = 1) of a stored
    /// contact state, N/m, for the critical time step (Rojek §3.4).
    pub fn stiffness(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        state: &StateOf<N, T>,
    ) -> (f64, f64) {
        let k_n = self
            .normal
            .time_step_stiffness(overlap, effective_radius, pair, &state.normal);
        let k_t = if T::ACTIVE {
            self.tangential
                .stiffness(&Self::resting_input(overlap, effective_radius, pair, k_n))
        } else {
            0.0
        };
        (k_n, k_t)
    }
}

/// Code that runs once per scene with the scene's laws as types
/// (`ContactLaw::visit`).
pub trait LawVisitor {
    /// What the visit returns.
    type Output;
    /// Run with the scene's law as the composed type `law`.
    fn visit<N: NormalModel, T: TangentialModel>(self, law: Composed<N, T>) -> Self::Output;
}
