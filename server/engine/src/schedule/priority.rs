//! Prioritisation: what the schedulers know about each candidate pair before any sphere test
//! (paper section 4, "a perceptual importance is attached to each collision").
//!
//! This runs over every candidate pair inside the frame's budget, so its cost is bounded by design:
//! each body is projected once per frame (its pixel position, its unit eye ray and its scale in the
//! model's unit per scene unit), and a pair then costs one projection of its centre, one square root
//! for the eye ray, one for the centre distance, and a table lookup for the fall-off
//! ([`Falloff`]). Degrees of visual angle are never computed per pair: a pair is in the priority
//! queue's first queue iff the chord between its eye ray and the fixation's is within the chord of
//! the threshold angle, which is the same test as comparing the angles.
//!
//! The pair's traversal state stays in [`crate::narrow_phase`]; what is computed here lives in
//! [`Priorities`], parallel to the candidate list.

use crate::budget::Meter;
use crate::falloff::Falloff;
use crate::math::Vec3;
use crate::narrow_phase::PairState;
use crate::perception::{EccentricityUnit, Viewer};
use crate::world::World;

/// Per-body view of one frame.
#[derive(Debug, Clone, Copy, Default)]
struct BodyView {
    /// Screen position (pixels).
    px: [f32; 2],
    /// Unit ray from the eye to the body's screen position.
    ray: [f32; 3],
}

/// Per-pair inputs of the schedulers, index-parallel to the narrow phase's pairs.
#[derive(Debug, Clone, Default)]
pub struct Priorities {
    /// F of the scheduling model on the pair's untested evidence (body centres): the paper's
    /// priority, higher first. 0 for pairs prioritisation did not reach.
    pub weight: Vec<f32>,
    /// Eccentricity fall-off F(1, e) at the pair's centre (1 for every pair without a fixation).
    pub falloff: Vec<f32>,
    /// The model's gap unit per scene unit at the pair (pixels or degrees per unit length).
    pub scale: Vec<f32>,
    /// Centre distance over twice the root radius: 1 is where the root spheres touch.
    pub dist: Vec<f32>,
    /// Inside the priority-queue eccentricity threshold.
    pub inner: Vec<bool>,
    /// Pairs prioritised this frame (the rest were cut off by a wall-clock deadline).
    pub reached: usize,
    body: Vec<BodyView>,
}

impl Priorities {
    /// No priorities for `n` pairs: every weight 0, every fall-off 1, no pair in the first queue
    /// (for schedulers that do not prioritise, or frames without a fixation).
    pub fn clear(&mut self, n: usize) {
        for v in [&mut self.weight, &mut self.scale, &mut self.dist] {
            v.clear();
            v.resize(n, 0.0);
        }
        self.falloff.clear();
        self.falloff.resize(n, 1.0);
        self.inner.clear();
        self.inner.resize(n, false);
        self.reached = 0;
    }
}

/// The constant part of prioritisation: display geometry, model and threshold.
#[derive(Debug, Clone)]
pub struct Prioritiser {
    falloff: Falloff,
    threshold_chord: f64,
    pitch: f64,
    centre: [f64; 2],
    distance: f64,
    /// Pixels per scene unit at depth 1 (the camera's focal length in pixels).
    focal: f32,
    eye: Vec3,
    inv_root_diameter: f32,
}

impl Prioritiser {
    /// For `viewer`, scheduling `model`, a first queue within `threshold_deg`, and sphere trees
    /// whose root has radius `root_radius`.
    pub fn new(
        viewer: &Viewer,
        model: &crate::perception::PerceptualModel,
        threshold_deg: f64,
        root_radius: f64,
    ) -> Self {
        let d = &viewer.display;
        let half = (0.5 * threshold_deg.clamp(0.0, 180.0)).to_radians();
        Self {
            falloff: Falloff::new(model),
            threshold_chord: 2.0 * half.sin(),
            pitch: d.pixel_pitch_cm(),
            centre: [0.5 * f64::from(d.width_px), 0.5 * f64::from(d.height_px)],
            distance: d.viewing_distance_cm,
            focal: viewer.focal_px() as f32,
            eye: viewer.eye,
            inv_root_diameter: (0.5 / root_radius) as f32,
        }
    }

    /// The unit eye ray of a screen point, in f64: the first-queue test compares it against the
    /// threshold, and pairs that sit on the threshold must fall on the side the angle says.
    #[inline]
    fn ray64(&self, px: [f64; 2]) -> [f64; 3] {
        let v = [
            (px[0] - self.centre[0]) * self.pitch,
            (px[1] - self.centre[1]) * self.pitch,
            self.distance,
        ];
        let inv = 1.0 / (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] * inv, v[1] * inv, v[2] * inv]
    }

    #[inline]
    fn ray(&self, px: [f32; 2]) -> [f32; 3] {
        let (pitch, distance) = (self.pitch as f32, self.distance as f32);
        let v = [
            (px[0] - self.centre[0] as f32) * pitch,
            (px[1] - self.centre[1] as f32) * pitch,
            distance,
        ];
        let inv = 1.0 / (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] * inv, v[1] * inv, v[2] * inv]
    }

    /// The lookup argument between two screen points: the chord of their eye rays (degrees unit)
    /// or their pixel distance.
    #[inline]
    fn arg(&self, a: &BodyView, b: &BodyView) -> f32 {
        match self.falloff.unit() {
            EccentricityUnit::Degrees => chord(a.ray, b.ray),
            EccentricityUnit::Pixels => (a.px[0] - b.px[0]).hypot(a.px[1] - b.px[1]),
        }
    }

    fn view_of(&self, viewer: &Viewer, p: Vec3) -> BodyView {
        let s = viewer.project(p);
        let px = [s[0] as f32, s[1] as f32];
        BodyView {
            px,
            ray: self.ray(px),
        }
    }

    /// Fill `out` for `pairs`. With a fixation (pixels), weights, fall-offs and the first queue
    /// follow it; without one every fall-off is 1 and no pair is in the first queue. Checks a
    /// wall-clock deadline every 64 pairs and stops when it has passed: pairs not reached keep
    /// weight 0 and stay in the second queue, so a budget smaller than prioritisation is still held.
    pub fn prioritise(
        &self,
        pairs: &[PairState],
        world: &World,
        viewer: &Viewer,
        fixation_px: Option<[f64; 2]>,
        out: &mut Priorities,
        meter: &mut Meter<'_>,
    ) {
        let n = pairs.len();
        for v in [&mut out.weight, &mut out.falloff, &mut out.scale, &mut out.dist] {
            v.clear();
            v.resize(n, 0.0);
        }
        out.inner.clear();
        out.inner.resize(n, false);
        out.reached = 0;
        out.body.clear();
        out.body
            .extend(world.position.iter().map(|&p| self.view_of(viewer, p)));
        let fix = fixation_px.map(|f| {
            let px = [f[0] as f32, f[1] as f32];
            let view = BodyView {
                px,
                ray: self.ray(px),
            };
            (view, self.ray64(f))
        });
        let degrees = self.falloff.unit() == EccentricityUnit::Degrees;
        for (k, p) in pairs.iter().enumerate() {
            // Sphere-test budgets do not count this work (it tests no spheres).
            if k % 64 == 0 && meter.exhausted_by_clock() {
                return;
            }
            let (a, b) = (p.a as usize, p.b as usize);
            let (pa, pb) = (world.position[a], world.position[b]);
            let centre_3d = (pa + pb) * 0.5;
            let d = (pb - pa).length() as f32;
            out.dist[k] = d * self.inv_root_diameter;
            // Scale: the screen size of a unit length at the pair's depth, in the model's unit
            // (a degree per pixel shrinks as cos^2 of the angle off the screen's axis).
            let depth = ((self.eye.z - centre_3d.z) as f32).max(1e-9);
            let px_per_unit = self.focal / depth;
            let (va, vb) = (&out.body[a], &out.body[b]);
            let g_arg = self.arg(va, vb);
            let c_px = viewer.project(centre_3d);
            let c = BodyView {
                px: [c_px[0] as f32, c_px[1] as f32],
                ray: self.ray([c_px[0] as f32, c_px[1] as f32]),
            };
            let scale = if degrees {
                let cos = c.ray[2];
                px_per_unit * (self.pitch / self.distance) as f32 * cos * cos * 57.295_78
            } else {
                px_per_unit
            };
            out.scale[k] = scale;
            let gap = self.falloff.eccentricity(g_arg);
            match &fix {
                Some((f, f_ray)) => {
                    let e_arg = self.arg(&c, f);
                    let fo = self.falloff.factor(e_arg);
                    out.falloff[k] = fo;
                    out.weight[k] = fo * gap;
                    out.inner[k] = chord64(self.ray64(c_px), *f_ray) <= self.threshold_chord;
                }
                None => {
                    out.falloff[k] = 1.0;
                    out.weight[k] = gap;
                }
            }
            out.reached = k + 1;
        }
    }
}

/// |u - v| for unit vectors: 2 sin(angle / 2).
#[inline]
fn chord(u: [f32; 3], v: [f32; 3]) -> f32 {
    let d = [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

/// |u - v| for unit vectors, in f64.
#[inline]
fn chord64(u: [f64; 3], v: [f64; 3]) -> f64 {
    let d = [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}
