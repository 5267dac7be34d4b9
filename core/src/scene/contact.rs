//! The `contact` block of a scene: the contact law, one block per role (normal,
//! damping, tangential with its friction, cohesion) and the lever-arm convention.
//!
//! ```json
//! {"normal": {"law": "hertz"}, "damping": {"kind": "critical_fraction", "xi": 0.9},
//!  "tangential": {"law": "mindlin_deresiewicz", "friction": 0.05}}
//! ```
//!
//! Each law's parameters and rules live in its own file under `contact/`; this file
//! holds what joins them to the rest of the scene: what a law needs of the materials,
//! and the friction coefficient of each pair of materials.

use super::materials::{MaterialNames, MaterialSpec};
use super::schema::Scene;
use crate::contact::ContactLaw;
use crate::contact::damping::Damping;
use crate::contact::lever_arm::LeverArm;
use crate::contact::model::{Needs, Roles};
use crate::contact::normal::NormalLaw;
use crate::contact::rolling::RollingLaw;
use crate::contact::tangential::TangentialLaw;
use crate::contact::tangential::families::Spring;
use crate::contact::van_der_waals::Cohesion;
use crate::error::Errors;
use crate::material::{Material, PairTable};
use serde::{Deserialize, Serialize};
use std::collections::HashSet;

/// The contact law, one block per role. The scene holds the law types themselves.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ContactSpec {
    /// The normal law (`law` tag and its parameters).
    pub normal: NormalLaw,
    /// The normal dashpot; absent means none.
    #[serde(default)]
    pub damping: Option<DampingSpec>,
    /// The tangential law with its friction; absent means frictionless.
    #[serde(default)]
    pub tangential: Option<FrictionSpec>,
    /// Attraction between surfaces near contact; absent means none.
    #[serde(default)]
    pub cohesion: Option<Cohesion>,
    /// Resistance to rolling (`law` tag and its parameters); absent means none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rolling: Option<RollingLaw>,
    /// Where a contact acts on spinning spheres: `mid_overlap` (default) or `lammps`
    /// (contact/lever_arm.rs).
    #[serde(default)]
    pub lever_arm: LeverArm,
}

impl ContactSpec {
    /// μ between the materials named `a` and `b`: their `friction_pairs` entry where
    /// listed, else the tangential block's μ (0 without one), as the pair table has it.
    pub fn friction_between(&self, a: &str, b: &str) -> f64 {
        self.tangential.as_ref().map_or(0.0, |t| {
            t.friction_pairs
                .iter()
                .find(|p| {
                    (p.materials[0] == a && p.materials[1] == b)
                        || (p.materials[0] == b && p.materials[1] == a)
                })
                .map_or(t.friction, |p| p.friction)
        })
    }

    /// The law the force loop runs (friction coefficients go to the pair table).
    pub fn law(&self) -> ContactLaw {
        ContactLaw {
            lever_arm: self.lever_arm,
            rolling: self.rolling,
            no_pull: self.damping.is_some_and(|d| d.limit),
            ..ContactLaw::new(
                self.normal,
                self.dashpot(),
                self.tangential.as_ref().map(|t| t.law),
                self.cohesion,
            )
        }
    }

    /// The dashpot's kind and coefficient, if there is one.
    pub fn dashpot(&self) -> Option<Damping> {
        self.damping.map(|d| d.kind)
    }
}

/// The `damping` block: the dashpot (its `kind` tag and parameters, inline) and whether
/// the total normal force is kept from pulling.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize, Serialize)]
pub struct DampingSpec {
    /// The dashpot.
    #[serde(flatten)]
    pub kind: Damping,
    /// The elastic plus damping normal force is clamped at zero, so the dashpot never
    /// pulls at the end of a contact: LAMMPS's `limit_damping`, LIGGGHTS's
    /// `limitForce on`. Off by default, as in both.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub limit: bool,
}

impl From<Damping> for DampingSpec {
    fn from(kind: Damping) -> Self {
        DampingSpec { kind, limit: false }
    }
}

/// Friction: the tangential law (its `law` tag and parameters, inline) plus μ and
/// per-pair overrides. Unknown fields are refused by the law's own type.
#[derive(Clone, Debug, Deserialize, Serialize)]
pub struct FrictionSpec {
    /// The tangential law.
    #[serde(flatten)]
    pub law: TangentialLaw,
    /// The friction coefficient μ of every pair not listed in `friction_pairs`.
    pub friction: f64,
    /// Per-material-pair friction overrides.
    #[serde(default)]
    pub friction_pairs: Vec<FrictionPair>,
}

/// μ of one unordered pair of materials (a particle–wall pair too).
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionPair {
    /// The two material names, in either order.
    pub materials: [String; 2],
    /// The friction coefficient μ of the pair.
    pub friction: f64,
}

/// What the contact law's rules read from the rest of the scene.
pub struct LawContext<'a> {
    /// The scene's materials.
    pub materials: &'a [MaterialSpec],
    /// Their names.
    pub names: &'a MaterialNames<'a>,
    /// The materials particles are made of (a law may need something of these only).
    pub particle_materials: HashSet<&'a str>,
    /// Whether the scene turns its particles.
    pub rotation: bool,
    /// Whether the scene grows its particles (a growth stage).
    pub growth: bool,
}

impl<'a> LawContext<'a> {
    /// The context of an ordinary scene: its particles are those it places, inserts
    /// and deposits.
    pub fn of(scene: &'a Scene, names: &'a MaterialNames<'a>) -> Self {
        LawContext {
            materials: &scene.materials,
            names,
            particle_materials: scene
                .particles
                .iter()
                .map(|p| p.material.as_str())
                .chain(scene.insert.iter().map(|i| i.material.as_str()))
                .chain(scene.deposit.iter().map(|d| d.material.as_str()))
                .collect(),
            rotation: scene.rotation.is_some(),
            growth: scene.growth.is_some(),
        }
    }
}

/// Each role's own rules, what the laws need of the materials and the scene, and
/// the friction pairs' materials; `at` is where the scene holds the block
/// (`contact`, or a die compaction's `die_compaction.fill.contact`).
pub fn validate(contact: &ContactSpec, at: &str, ctx: &LawContext, e: &mut Errors) {
    let roles = Roles {
        normal: &contact.normal,
        damping: contact.damping.as_ref().map(|d| &d.kind),
    };
    let normal = &contact.normal;
    contact.normal.check(&format!("{at}.normal"), e);
    require(
        e,
        ctx,
        normal.needs(),
        &format!("{at}.normal.law '{}'", normal.name()),
    );
    if let Some(damping) = &contact.damping {
        damping.kind.check(&format!("{at}.damping"), roles, e);
        if normal.has_own_dissipation() {
            e.push(
                format!("{at}.damping"),
                format!(
                    "must be absent with {at}.normal.law '{}', which dissipates by itself",
                    normal.name()
                ),
            );
        }
    }
    if let Some(t) = &contact.tangential {
        t.law.check(&format!("{at}.tangential"), roles, e);
        require(
            e,
            ctx,
            t.law.needs(),
            &format!("{at}.tangential.law '{}'", t.law.name()),
        );
        e.non_negative(format!("{at}.tangential.friction"), t.friction);
        // A pair is unordered: its key is its two names sorted.
        let mut listed = HashSet::new();
        for (k, fp) in t.friction_pairs.iter().enumerate() {
            let path = format!("{at}.tangential.friction_pairs[{k}]");
            let mut key = fp.materials.clone();
            key.sort();
            if !listed.insert(key.clone()) {
                e.push(
                    format!("{path}.materials"),
                    format!("the pair {key:?} is listed twice"),
                );
            }
            e.non_negative(format!("{path}.friction"), fp.friction);
            for (s, name) in fp.materials.iter().enumerate() {
                if !ctx.names.known(name) {
                    e.push(
                        format!("{path}.materials[{s}]"),
                        format!("unknown material '{name}'"),
                    );
                }
            }
        }
    }
    if let Some(cohesion) = &contact.cohesion {
        cohesion.check(&format!("{at}.cohesion"), e);
    }
    if let Some(rolling) = &contact.rolling {
        rolling_rules(rolling, contact, at, ctx, e);
    }
    if normal.mdr().is_some() {
        mdr_rules(contact, at, ctx, e);
    }
}

/// Rolling resistance acts on spins, and joins a tangential law that keeps one spring
/// (`contact/rolling/mod.rs`).
fn rolling_rules(
    rolling: &RollingLaw,
    contact: &ContactSpec,
    at: &str,
    ctx: &LawContext,
    e: &mut Errors,
) {
    let path = format!("{at}.rolling");
    rolling.check(&path, e);
    let spring = contact
        .tangential
        .as_ref()
        .is_some_and(|t| Spring::of(t.law).is_some());
    if !spring {
        e.push(
            format!("{path}.law"),
            format!(
                "'{}' needs {at}.tangential with a law that keeps one spring (cundall_strack, mindlin_no_slip, storakers, liggghts_history or lammps_linear_history)",
                rolling.name()
            ),
        );
    }
    if !ctx.rotation {
        e.push(
            path,
            "needs \"rotation\": a rolling resistance acts on the particles' spins",
        );
    }
}

/// What MDR cannot be combined with: its per-particle state has no place for a
/// growing radius or an attraction across a gap, and the contact records evaluate the
/// laws without the particles' state.
fn mdr_rules(contact: &ContactSpec, at: &str, ctx: &LawContext, e: &mut Errors) {
    let why = |what: &str| format!("cannot be combined with {at}.normal.law 'mdr': {what}");
    if contact.cohesion.is_some() {
        e.push(
            format!("{at}.cohesion"),
            why("mdr has its own adhesion (surface_energy)"),
        );
    }
    if ctx.growth {
        e.push(
            "growth",
            why("mdr grows the apparent radius itself from the plastically displaced volume"),
        );
    }
}

/// What a law needs of the materials and the scene (`Needs`), asked of every
/// material; `by` names the law in the message.
fn require(e: &mut Errors, ctx: &LawContext, needs: Needs, by: &str) {
    if let Some(what_for) = needs.elastic {
        for (k, m) in ctx.materials.iter().enumerate() {
            for (field, given) in [
                ("youngs_modulus", m.youngs_modulus.is_some()),
                ("poisson_ratio", m.poisson_ratio.is_some()),
            ] {
                if !given && !m.rigid {
                    e.push(
                        format!("materials[{k}].{field}"),
                        format!("is required by {by}{what_for}"),
                    );
                }
            }
        }
    }
    if needs.hollomon {
        for (k, m) in ctx.materials.iter().enumerate() {
            if m.hollomon.is_none() && ctx.particle_materials.contains(m.name.as_str()) {
                e.push(
                    format!("materials[{k}].hollomon"),
                    format!("is required by {by} for every particle material"),
                );
            }
        }
        let exponents: Vec<(usize, f64)> = ctx
            .materials
            .iter()
            .enumerate()
            .filter_map(|(k, m)| m.hollomon.as_ref().map(|h| (k, h.exponent)))
            .collect();
        if let Some(&(first, m0)) = exponents.first() {
            for &(k, m) in &exponents[1..] {
                if m != m0 {
                    e.push(
                        format!("materials[{k}].hollomon.exponent"),
                        format!("must equal materials[{first}].hollomon.exponent ({m0}): Rojek eq 18 mixes one exponent, got {m}"),
                    );
                }
            }
        }
    }
    if let Some(rule) = needs.rotation
        && !ctx.rotation
    {
        e.push("rotation", rule);
    }
}

/// The pair table: the mixed constants of every pair of materials, with μ from
/// `friction_pairs` where listed, else the tangential block's μ (0 without one).
pub fn pair_table(
    contact: &ContactSpec,
    materials: &[Material],
    material_id: &dyn Fn(&str) -> usize,
) -> PairTable {
    let (default_friction, overrides): (f64, Vec<(usize, usize, f64)>) = match &contact.tangential {
        Some(FrictionSpec {
            friction,
            friction_pairs,
            ..
        }) => (
            *friction,
            friction_pairs
                .iter()
                .map(|fp| {
                    (
                        material_id(&fp.materials[0]),
                        material_id(&fp.materials[1]),
                        fp.friction,
                    )
                })
                .collect(),
        ),
        None => (0.0, Vec::new()),
    };
    let mut table = PairTable::new(materials, |a, b| {
        overrides
            .iter()
            .find(|&&(x, y, _)| (x, y) == (a, b) || (y, x) == (a, b))
            .map_or(default_friction, |o| o.2)
    });
    for pair in table.pairs_mut() {
        pair.law_constant = contact.normal.pair_constant(pair);
    }
    table
}
