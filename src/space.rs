//! The simulation domain: which axes are periodic and over what interval.
//!
//! Along a periodic axis with interval [lo, lo + L) a particle leaving one face
//! re-enters through the opposite one, and two particles interact through their
//! nearest images (minimum-image convention). This models an unbounded bed with
//! finitely many particles, as the four periodic side faces of Zhong 2009 §6.1 do.
//! The convention is exact only while every interaction range is below L/2, which
//! the scene validator enforces (L > 2·(2 R_max + skin + cohesion reach)).

use crate::particles::Vec3;

#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Space {
    /// Per axis: `Some((lo, length))` when periodic.
    pub periodic: [Option<(f64, f64)>; 3],
}

impl Space {
    pub fn open() -> Self {
        Space::default()
    }

    pub fn is_periodic(&self) -> bool {
        self.periodic.iter().any(Option::is_some)
    }

    /// Vector from `b` to `a` to its nearest image: a − b, wrapped into [−L/2, L/2]
    /// along periodic axes.
    #[inline]
    pub fn displacement(&self, a: &Vec3, b: &Vec3) -> Vec3 {
        let mut d = a - b;
        for k in 0..3 {
            if let Some((_, length)) = self.periodic[k] {
                // Positions are wrapped every step, so |d| < length and the nearest
                // image is one period away: shifting by ±L is what d − L·round(d/L)
                // gives there, without the libm call (a pair straddling a face pays
                // it every step). `round` is kept for the rare farther case.
                let half = 0.5 * length;
                if d[k].abs() > half {
                    d[k] -= length.copysign(d[k]);
                    if d[k].abs() > half {
                        d[k] -= length * (d[k] / length).round();
                    }
                }
            }
        }
        d
    }

    /// Move a position back into the periodic interval along every periodic axis.
    #[inline]
    pub fn wrap(&self, x: &mut Vec3) {
        for k in 0..3 {
            if let Some((lo, length)) = self.periodic[k] {
                if x[k] >= lo && x[k] < lo + length {
                    continue;
                }
                let shifted = (x[k] - lo).rem_euclid(length);
                // rem_euclid can return `length` itself for tiny negative inputs.
                x[k] = lo + if shifted >= length { 0.0 } else { shifted };
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_image_and_wrap() {
        let s = Space {
            periodic: [Some((0.0, 1.0)), None, None],
        };
        let d = s.displacement(&Vec3::new(0.95, 0.0, 0.0), &Vec3::new(0.05, 0.0, 0.0));
        assert!((d[0] + 0.1).abs() < 1e-15);
        // More than a period apart (unwrapped positions): still the nearest image.
        let far = s.displacement(&Vec3::new(1.75, 0.0, 0.0), &Vec3::new(0.0, 0.0, 0.0));
        assert!((far[0] + 0.25).abs() < 1e-15);
        let mut x = Vec3::new(-0.25, 7.0, 0.0);
        s.wrap(&mut x);
        assert!((x[0] - 0.75).abs() < 1e-15 && x[1] == 7.0);
        let mut y = Vec3::new(-1e-18, 0.0, 0.0);
        s.wrap(&mut y);
        assert!(y[0] >= 0.0 && y[0] < 1.0);
    }
}
