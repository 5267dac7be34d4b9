//! Coordination number: contacts per particle.
//!
//! Two particles are in contact when their overlap, with the minimum-image
//! separation d_ij, exceeds minus a tolerance:
//!
//!   δ_ij = r_i + r_j − |d_ij| > −tol,
//!
//! so `tol > 0` also counts gaps narrower than tol — contacts that a relaxed packing
//! leaves open by a hair. Only particle–particle contacts count; wall contacts do not.
//! Candidate pairs come from the caller's broad phase (any superset of the contacting
//! pairs, each unordered pair once; i = j is ignored).
//!
//! The mean coordination number over a set P of counted particles is
//!
//!   Z = Σ_{i∈P} z_i / |P|,
//!
//! z_i the number of contacts of i. Two filters, both optional:
//!
//! * **Rattlers.** Particles with fewer than m contacts carry no load in a static
//!   packing and are removed, iteratively: removing one lowers its neighbours'
//!   counts, which may make them rattlers too (the usual definition in the jamming
//!   literature). The natural thresholds in 3D follow from force balance: without
//!   friction a particle needs at least d + 1 = 4 contacts to balance generic normal
//!   forces, so m = 4; with friction two opposed contacts can balance, so m = 2. The
//!   caller chooses. Z then counts only contacts between non-rattlers, and rattlers
//!   leave P.
//! * **Interior.** Only particles whose centres lie in a given region enter P (to
//!   remove the wall effect); their contacts with particles outside still count.
//!   Rattler removal runs on the whole packing first, so the filter does not create
//!   artificial rattlers at the region's edge.
//!
//! A particle touching only a wall has z = 0 here; with a rattler filter such
//! particles near walls are removed, which is one more reason to use an interior.

use crate::error::{Result, TampError};
use crate::measure::region::Region;
use crate::particles::Vec3;
use crate::space::Space;

/// The default (tolerance 0, no rattler filter, no interior) counts the overlapping
/// pairs of every particle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CoordinationOptions {
    /// Gap still counted as a contact, m (≥ 0).
    pub tolerance: f64,
    /// Remove particles with fewer contacts than this, iteratively; `None` keeps all.
    pub rattler_below: Option<usize>,
    /// Count only particles whose centre lies in this region.
    pub interior: Option<Region>,
}

/// Coordination numbers of a packing: the mean Z over the counted particles, each
/// particle's count z_i and their distribution.
#[derive(Clone, Debug, PartialEq)]
pub struct Coordination {
    /// Z over the counted particles (0 when none are counted).
    pub mean: f64,
    /// How many particles were counted.
    pub counted: usize,
    /// Rattlers removed from the whole packing (also outside the interior).
    pub rattlers: usize,
    /// Per particle: contacts with non-rattlers (all contacts without a rattler
    /// filter); a rattler's entry is its count when it was removed.
    pub contacts: Vec<u32>,
    /// Per particle: whether it was removed as a rattler.
    pub is_rattler: Vec<bool>,
    /// `histogram[z]` = counted particles with z contacts.
    pub histogram: Vec<usize>,
}

/// Coordination of the spheres (`positions`, `radii`, m) over the candidate `pairs`,
/// with the contact tolerance and the rattler and interior filters of `options`.
/// Errors (naming the argument) on mismatched lengths, a negative or non-finite
/// tolerance, an invalid interior region, or a pair index out of range.
pub fn coordination(
    positions: &[Vec3],
    radii: &[f64],
    space: &Space,
    pairs: &[(u32, u32)],
    options: &CoordinationOptions,
) -> Result<Coordination> {
    let n = positions.len();
    if radii.len() != n {
        return Err(TampError::input(
            "radii",
            format!(
                "one radius per position expected, got {} for {n}",
                radii.len()
            ),
        ));
    }
    if !(options.tolerance >= 0.0 && options.tolerance.is_finite()) {
        return Err(TampError::input(
            "tolerance",
            format!("must be finite and ≥ 0, got {}", options.tolerance),
        ));
    }
    if let Some(defect) = options.interior.as_ref().and_then(Region::defect) {
        return Err(TampError::input("interior", defect));
    }
    let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); n];
    for &(i, j) in pairs {
        let (iu, ju) = (i as usize, j as usize);
        if iu >= n || ju >= n {
            return Err(TampError::input(
                "pairs",
                format!("pair ({i}, {j}) refers past the {n} particles"),
            ));
        }
        if i == j {
            continue;
        }
        let gap = space.displacement(&positions[iu], &positions[ju]).norm() - radii[iu] - radii[ju];
        if gap < options.tolerance {
            neighbours[iu].push(j);
            neighbours[ju].push(i);
        }
    }
    let mut contacts: Vec<u32> = neighbours.iter().map(|v| v.len() as u32).collect();
    let mut is_rattler = vec![false; n];
    if let Some(m) = options.rattler_below {
        let mut stack: Vec<usize> = (0..n).filter(|&i| (contacts[i] as usize) < m).collect();
        for &i in &stack {
            is_rattler[i] = true;
        }
        while let Some(i) = stack.pop() {
            for &j in &neighbours[i] {
                let j = j as usize;
                if is_rattler[j] {
                    continue;
                }
                contacts[j] -= 1;
                if (contacts[j] as usize) < m {
                    is_rattler[j] = true;
                    stack.push(j);
                }
            }
        }
    }
    let mut histogram = Vec::new();
    let mut counted = 0usize;
    let mut total = 0u64;
    for i in 0..n {
        if is_rattler[i]
            || options
                .interior
                .as_ref()
                .is_some_and(|region| !region.contains_point(&positions[i]))
        {
            continue;
        }
        let z = contacts[i] as usize;
        if histogram.len() <= z {
            histogram.resize(z + 1, 0);
        }
        histogram[z] += 1;
        counted += 1;
        total += z as u64;
    }
    Ok(Coordination {
        mean: if counted > 0 {
            total as f64 / counted as f64
        } else {
            0.0
        },
        counted,
        rattlers: is_rattler.iter().filter(|&&r| r).count(),
        contacts,
        is_rattler,
        histogram,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::detect::brute::candidate_pairs;

    fn fcc(n: usize, a: f64) -> (Vec<Vec3>, Vec<f64>, Space) {
        let basis = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(0.5, 0.5, 0.0),
            Vec3::new(0.5, 0.0, 0.5),
            Vec3::new(0.0, 0.5, 0.5),
        ];
        let mut x = Vec::new();
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    for b in &basis {
                        x.push((Vec3::new(i as f64, j as f64, k as f64) + b) * a);
                    }
                }
            }
        }
        let r = vec![a / (2.0 * 2f64.sqrt()); x.len()];
        let l = n as f64 * a;
        (
            x,
            r,
            Space {
                periodic: [Some((0.0, l)); 3],
            },
        )
    }

    #[test]
    fn periodic_fcc_has_twelve_contacts_each() {
        let (x, r, space) = fcc(3, 1.0);
        let pairs = candidate_pairs(&x, &r, 0.05, &space);
        let options = CoordinationOptions {
            tolerance: 1e-9,
            ..Default::default()
        };
        let c = coordination(&x, &r, &space, &pairs, &options).unwrap();
        assert_eq!(c.mean, 12.0);
        assert_eq!(c.histogram[12], x.len());
        // Touching exactly, without a tolerance, is a coin toss in floating point;
        // shrinking the balls by a hair opens every contact.
        let small: Vec<f64> = r.iter().map(|r| r * (1.0 - 1e-9)).collect();
        let open = coordination(&x, &small, &space, &pairs, &CoordinationOptions::default());
        assert_eq!(open.unwrap().mean, 0.0);
    }

    /// A chain 0–1–2–3 plus a tetrahedron 4–7 (each with 3 contacts) plus a loose
    /// particle 8. With m = 2 the chain's ends go, then its middle; with m = 4 all go.
    #[test]
    fn rattlers_are_removed_iteratively() {
        let mut x = vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(3.0, 0.0, 0.0),
        ];
        let s = 1.0 / 2f64.sqrt();
        for p in [
            Vec3::new(1.0, 1.0, 1.0),
            Vec3::new(1.0, -1.0, -1.0),
            Vec3::new(-1.0, 1.0, -1.0),
            Vec3::new(-1.0, -1.0, 1.0),
        ] {
            x.push(p * s * 0.5 + Vec3::new(10.0, 0.0, 0.0));
        }
        x.push(Vec3::new(20.0, 0.0, 0.0));
        let r = vec![0.5; x.len()];
        let space = Space::open();
        let pairs = candidate_pairs(&x, &r, 0.1, &space);
        let with_rattlers_below = |rattler_below| {
            let options = CoordinationOptions {
                tolerance: 1e-9,
                rattler_below,
                interior: None,
            };
            coordination(&x, &r, &space, &pairs, &options).unwrap()
        };
        let all = with_rattlers_below(None);
        assert_eq!(all.contacts, vec![1, 2, 2, 1, 3, 3, 3, 3, 0]);
        assert_eq!(all.histogram, vec![1, 2, 2, 4]);
        assert!((all.mean - 18.0 / 9.0).abs() < 1e-15);
        let two = with_rattlers_below(Some(2));
        assert_eq!(two.rattlers, 5);
        assert_eq!(two.counted, 4);
        assert_eq!(two.mean, 3.0);
        let four = with_rattlers_below(Some(4));
        assert_eq!((four.rattlers, four.counted, four.mean), (9, 0, 0.0));
    }

    #[test]
    fn interior_counts_contacts_with_outside_particles() {
        let x = vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
        ];
        let r = vec![0.5; 3];
        let space = Space::open();
        let pairs = [(0, 1), (1, 2), (0, 2)];
        let c = coordination(
            &x,
            &r,
            &space,
            &pairs,
            &CoordinationOptions {
                tolerance: 1e-12,
                rattler_below: None,
                interior: Some(Region::Sphere {
                    centre: Vec3::new(1.0, 0.0, 0.0),
                    radius: 0.2,
                }),
            },
        )
        .unwrap();
        assert_eq!((c.counted, c.mean), (1, 2.0));
        assert!(coordination(&x, &r, &space, &[(0, 3)], &Default::default()).is_err());
    }
}
