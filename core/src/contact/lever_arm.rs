//! Where a contact acts on a spinning sphere: the lever arms that turn the spins into
//! the contact-point velocity and the tangential force into torques. A scene declares
//! the convention (`contact.lever_arm`). The force loop picks it per contact, a branch
//! on a value fixed for the run: as a type, like the laws, it compiled the whole loop
//! once more for every law (docs/performance.md, "Compile time").
//!
//! `mid_overlap` (default; tamp's, and LIGGGHTS 3.8's, fix_wall_gran.cpp and
//! pair_gran.cpp): the contact point lies in the middle of the overlap, at
//! ℓ_i = R_i − δ/2 from centre i, for pairs and walls alike:
//!
//!   v_c = v_i − v_j − (ℓ_i ω_i + ℓ_j ω_j) × n,   T_i = −ℓ_i n × F_t,   T_j = −ℓ_j n × F_t
//!
//! The two arms add up to the centre distance, so the torques conserve angular
//! momentum exactly.
//!
//! `lammps` (LAMMPS 22 Jul 2025, src/GRANULAR/granular_model.cpp
//! `GranularModel::calculate_forces`, and fix_wall_gran.cpp, which sets the wall's
//! radius and spin to 0): the spin part of the contact velocity takes the full radii,
//! (R_i ω_i + R_j ω_j) × n; the torques take R − δ/2 for a pair but the full R_i for a
//! wall:
//!
//!   pair: v_c = v_i − v_j − (R_i ω_i + R_j ω_j) × n,  T_{i,j} = −(R_{i,j} − δ/2) n × F_t
//!   wall: v_c = v_i − v_w − R_i ω_i × n,              T_i = −R_i n × F_t
//!
//! The two differ by δ/R in the spin terms (docs/lammps.md, behaviours found).
//!
//! `full_radius` (LAMMPS's `pair_style gran/hooke/history`, pair_gran_hooke_history.cpp
//! `PairGranHookeHistory::compute`): the full radii in the contact velocity and in the
//! torques, pairs and walls:
//!
//!   v_c = v_i − v_j − (R_i ω_i + R_j ω_j) × n,   T_{i,j} = −R_{i,j} n × F_t
//!
//! The arms of a pair add up to R_i + R_j, more than the centre distance by δ, so the
//! torques of a sliding or sticking contact change the pair's angular momentum by δ/R
//! of their moment.

/// The scene's convention (`contact.lever_arm`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LeverArm {
    /// R − δ/2 everywhere (tamp, LIGGGHTS 3.8).
    #[default]
    MidOverlap,
    /// LAMMPS 22 Jul 2025 `pair granular` and `fix wall/gran granular`.
    Lammps,
    /// LAMMPS's `pair_style gran/hooke/history`: R everywhere.
    FullRadius,
}

impl LeverArm {
    /// The convention's name in the scene file.
    pub fn name(&self) -> &'static str {
        match self {
            LeverArm::MidOverlap => "mid_overlap",
            LeverArm::Lammps => "lammps",
            LeverArm::FullRadius => "full_radius",
        }
    }
}

/// The arms of one contact: `velocity` multiplies a spin in the contact-point
/// velocity, `torque` the tangential force in the torque.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arms {
    /// Arm multiplying the sphere's spin in the contact-point velocity, m.
    pub velocity: f64,
    /// Arm multiplying the tangential force in the sphere's torque, m.
    pub torque: f64,
}

impl LeverArm {
    /// The arms of a sphere of radius `radius` in a pair contact of overlap `overlap`.
    #[inline(always)]
    pub fn pair(self, radius: f64, overlap: f64) -> Arms {
        match self {
            LeverArm::MidOverlap => {
                let arm = radius - 0.5 * overlap;
                Arms {
                    velocity: arm,
                    torque: arm,
                }
            }
            LeverArm::Lammps => Arms {
                velocity: radius,
                torque: radius - 0.5 * overlap,
            },
            LeverArm::FullRadius => Arms {
                velocity: radius,
                torque: radius,
            },
        }
    }

    /// The arms of a sphere of radius `radius` on a wall, overlap `overlap`.
    #[inline(always)]
    pub fn wall(self, radius: f64, overlap: f64) -> Arms {
        match self {
            LeverArm::MidOverlap => self.pair(radius, overlap),
            LeverArm::Lammps | LeverArm::FullRadius => Arms {
                velocity: radius,
                torque: radius,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mid_overlap_arms_of_a_pair_add_up_to_the_centre_distance() {
        let (ri, rj, d) = (1e-3, 2e-3, 1e-5);
        let sum = LeverArm::MidOverlap.pair(ri, d).torque + LeverArm::MidOverlap.pair(rj, d).torque;
        assert!((sum - (ri + rj - d)).abs() < 1e-18);
    }

    #[test]
    fn lammps_takes_full_radii_except_for_pair_torques() {
        let (r, d) = (1e-3, 1e-5);
        assert_eq!(LeverArm::Lammps.pair(r, d).velocity, r);
        assert_eq!(LeverArm::Lammps.pair(r, d).torque, r - 0.5 * d);
        assert_eq!(
            LeverArm::Lammps.wall(r, d),
            Arms {
                velocity: r,
                torque: r
            }
        );
    }

    #[test]
    fn full_radius_takes_the_full_radii_everywhere() {
        let (r, d) = (1e-3, 1e-5);
        let full = Arms {
            velocity: r,
            torque: r,
        };
        assert_eq!(LeverArm::FullRadius.pair(r, d), full);
        assert_eq!(LeverArm::FullRadius.wall(r, d), full);
    }

    #[test]
    fn the_scene_names_the_convention() {
        let l: LeverArm = serde_json::from_str("\"lammps\"").unwrap();
        assert_eq!(l, LeverArm::Lammps);
        assert_eq!(LeverArm::default().name(), "mid_overlap");
        assert!(serde_json::from_str::<LeverArm>("\"full\"").is_err());
    }
}
