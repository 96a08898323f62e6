//! The star shape of the paper's test application (section 2, figure 2; dimensions from DESIGN.md):
//! a core ball of radius 0.3R and six spikes along ±x, ±y, ±z, each a cone whose base disc of radius
//! 0.25R is centred at the origin and whose apex is at distance R.
//!
//! The octree that builds the sphere tree needs an *exact* cell-versus-shape test, or cells that only
//! graze a spike tip would be dropped or kept at random. Both tests here are closed-form: the ball
//! against a box is the squared distance from the origin to the box; a cone against a box reduces to
//! one dimension because the cone's radius only shrinks along its axis, so the best point is at the
//! box's nearest axial coordinate and its nearest radial distance (see [`Star::cell_intersects`]).

use serde::{Deserialize, Serialize};

use crate::math::Vec3;

/// Core ball radius as a fraction of R.
pub const CORE_FRACTION: f64 = 0.3;
/// Spike base radius as a fraction of R.
pub const SPIKE_BASE_FRACTION: f64 = 0.25;

/// The star shape with bounding radius `radius` (R).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Star {
    /// Bounding radius R: the spike apexes lie at this distance from the centre.
    pub radius: f64,
    /// Core ball radius (0.3R).
    pub core_radius: f64,
    /// Spike base disc radius (0.25R).
    pub spike_base_radius: f64,
}

/// Distance from 0 to the interval [lo, hi] (0 if it contains 0).
fn interval_distance(lo: f64, hi: f64) -> f64 {
    if lo > 0.0 {
        lo
    } else if hi < 0.0 {
        -hi
    } else {
        0.0
    }
}

impl Star {
    /// The canonical star of bounding radius `radius`.
    pub fn new(radius: f64) -> Self {
        Self {
            radius,
            core_radius: CORE_FRACTION * radius,
            spike_base_radius: SPIKE_BASE_FRACTION * radius,
        }
    }

    /// Whether `p` (body frame) is inside the closed shape.
    pub fn contains(&self, p: Vec3) -> bool {
        if p.length_squared() <= self.core_radius * self.core_radius {
            return true;
        }
        let c = p.to_array();
        (0..3).any(|axis| {
            let along = c[axis].abs();
            let (u, v) = (c[(axis + 1) % 3], c[(axis + 2) % 3]);
            along <= self.radius
                && (u * u + v * v).sqrt() <= self.spike_base_radius * (1.0 - along / self.radius)
        })
    }

    /// Whether the open box (`lo`, `hi`) meets the interior of the shape.
    ///
    /// Open against open, so a cell that only touches the shape along a face, edge or point (a set of
    /// zero volume) is not counted: such a cell would add a sphere that covers nothing. A spike along
    /// +axis is { 0 <= t <= R, rho <= b (1 - t/R) }: rho's bound decreases in t, so the box meets the
    /// open cone iff at the box's smallest admissible t the box's smallest rho is strictly below it.
    pub fn cell_intersects(&self, lo: Vec3, hi: Vec3) -> bool {
        let d2 = (0..3)
            .map(|i| interval_distance(lo[i], hi[i]).powi(2))
            .sum::<f64>();
        if d2 < self.core_radius * self.core_radius {
            return true;
        }
        (0..3).any(|axis| {
            let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
            let rho = interval_distance(lo[i], hi[i]).hypot(interval_distance(lo[j], hi[j]));
            [(lo[axis], hi[axis]), (-hi[axis], -lo[axis])]
                .into_iter()
                .any(|(a, b)| {
                    let t = a.max(0.0);
                    t < b.min(self.radius) && rho < self.spike_base_radius * (1.0 - t / self.radius)
                })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contains_core_spikes_and_not_between() {
        let s = Star::new(1.0);
        assert!(s.contains(Vec3::ZERO));
        assert!(s.contains(Vec3::new(0.29, 0.0, 0.0)));
        assert!(s.contains(Vec3::new(0.0, -0.99, 0.0)));
        assert!(s.contains(Vec3::new(0.0, 0.0, 1.0)));
        assert!(!s.contains(Vec3::new(0.0, 0.0, 1.01)));
        assert!(!s.contains(Vec3::new(0.5, 0.5, 0.0)));
        assert!(!s.contains(Vec3::new(0.5, 0.2, 0.0)));
        assert!(s.contains(Vec3::new(0.5, 0.12, 0.0)));
    }

    #[test]
    fn cell_test_agrees_with_point_sampling() {
        // A cell meets the shape's interior iff some interior sample point is in the shape (up to
        // sampling resolution): sample strictly inside and check no sampled hit is ever missed.
        let s = Star::new(1.0);
        let n = 8;
        let w = 2.0 / n as f64;
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    let lo = Vec3::new(
                        -1.0 + i as f64 * w,
                        -1.0 + j as f64 * w,
                        -1.0 + k as f64 * w,
                    );
                    let hi = lo + Vec3::splat(w);
                    let m = 12;
                    let mut sampled = false;
                    for a in 0..m {
                        for b in 0..m {
                            for c in 0..m {
                                let f = Vec3::new(a as f64 + 0.5, b as f64 + 0.5, c as f64 + 0.5)
                                    / m as f64;
                                if s.contains(lo + f * w) {
                                    sampled = true;
                                }
                            }
                        }
                    }
                    if sampled {
                        assert!(s.cell_intersects(lo, hi), "missed cell {lo}..{hi}");
                    }
                }
            }
        }
    }
}
