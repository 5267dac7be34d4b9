//! The simulation domain: which axes are periodic and over what interval.
//!
//! Along a periodic axis with interval [lo, lo + L) a particle leaving one face
//! re-enters through the opposite one, and two particles interact through their
//! nearest images (minimum-image convention). This models an unbounded bed with
//! finitely many particles, as the four periodic side faces of Zhong 2009 §6.1 do.
//! The convention is exact only while every interaction range is below L/2, which
//! the scene validator enforces (L > 2·(2 R_max + skin + cohesion reach)).

use crate::particles::Vec3;

/// The simulation domain: per axis, open or periodic over an interval.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Space {
    /// Per axis: `Some((lo, length))` when periodic.
    pub periodic: [Option<(f64, f64)>; 3],
}

impl Space {
    /// Unbounded along every axis, no periodic images.
    pub fn open() -> Self {
        Space::default()
    }

    /// Whether any axis is periodic.
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

    /// The nearest-image rule unpacked for hot loops (`MinimumImage::displacement`).
    pub fn minimum_image(&self) -> MinimumImage {
        let mut image = MinimumImage {
            half: [f64::INFINITY; 3],
            length: [0.0; 3],
        };
        for k in 0..3 {
            if let Some((_, length)) = self.periodic[k] {
                image.half[k] = 0.5 * length;
                image.length[k] = length;
            }
        }
        image
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

/// `Space::displacement` with each axis's half period taken out of its `Option`
/// once: an open axis has an infinite half period, which no |d| exceeds, so it is
/// never shifted. The arithmetic is `Space::displacement`'s operation for
/// operation (the same results to the bit); only the per-axis test of the `Option`
/// is gone from the loops over pairs and particles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MinimumImage {
    half: [f64; 3],
    length: [f64; 3],
}

impl MinimumImage {
    /// Vector from `b` to `a` to its nearest image (as `Space::displacement`).
    #[inline(always)]
    pub fn displacement(&self, a: &Vec3, b: &Vec3) -> Vec3 {
        let mut d = a - b;
        for k in 0..3 {
            let (half, length) = (self.half[k], self.length[k]);
            if d[k].abs() > half {
                d[k] -= length.copysign(d[k]);
                if d[k].abs() > half {
                    d[k] -= length * round(d[k] / length);
                }
            }
        }
        d
    }
}

/// `f64::round` (half away from zero) without its library call, which on the
/// baseline x86-64 target (no rounding instruction) makes the loops that may reach
/// it keep their values on the stack. The same result to the bit: the fraction
/// x − trunc(x) is exact below 2⁵², where the value is rounded by hand; from 2⁵²
/// on (and ±∞, NaN) the value is its own rounding; `copysign` keeps the sign of a
/// result of zero (−0.3 rounds to −0.0).
#[inline(always)]
fn round(x: f64) -> f64 {
    if x.is_nan() || x.abs() >= 4_503_599_627_370_496.0 {
        return x;
    }
    let t = x as i64 as f64;
    let r = if (x - t).abs() >= 0.5 {
        t + 1.0f64.copysign(x)
    } else {
        t
    };
    r.copysign(x)
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
        for x in [
            0.0,
            -0.0,
            0.3,
            -0.3,
            0.5,
            -0.5,
            0.49999999999999994,
            -0.49999999999999994,
            1.5,
            -2.5,
            2.4999999999999996,
            1e15 + 0.5,
            -1e15 - 0.5,
            4503599627370495.5,
            4503599627370496.0,
            1e300,
            -1e300,
            5e-324,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ] {
            assert_eq!(round(x).to_bits(), x.round().to_bits(), "round({x})");
        }
        assert!(round(f64::NAN).is_nan());
        let image = s.minimum_image();
        for (a, b) in [
            (Vec3::new(0.95, 3.0, -2.0), Vec3::new(0.05, -4.0, 1.0)),
            (Vec3::new(1.75, 0.0, 0.0), Vec3::zeros()),
            (Vec3::new(-0.3, 1e9, 0.1), Vec3::new(0.4, -1e9, 0.2)),
        ] {
            assert_eq!(image.displacement(&a, &b), s.displacement(&a, &b));
        }
        let mut y = Vec3::new(-1e-18, 0.0, 0.0);
        s.wrap(&mut y);
        assert!(y[0] >= 0.0 && y[0] < 1.0);
    }
}
