//! Prioritisation: what the schedulers know about each candidate pair before any sphere test
//! (paper section 4, "a perceptual importance is attached to each collision").
//!
//! This runs over every candidate pair inside the frame's budget, so its cost is bounded by design:
//! each body is projected once per frame (its pixel position, its unit eye ray and its scale in the
//! model's unit per scene unit), and a pair then costs one projection of its centre, one square root
//! for the eye ray, one for the centre distance, and a table lookup for the fall-off
//! (`Falloff`). Degrees of visual angle are never computed per pair: a pair is in the priority
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
    /// The model's gap unit per scene unit at the body (pixels or degrees per unit length).
    scale: f32,
}

/// What a scheduler needs from prioritisation beyond distances, scales and fall-offs.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Needs {
    /// The priority-queue split (exact against the threshold angle).
    pub inner: bool,
    /// The paper's weight F(g', e) on the untested evidence.
    pub weight: bool,
    /// Per-body values only ([`Priorities::body_records`], [`Priorities::body_scale`]): the
    /// scheduler prices pairs itself, so no per-pair pass is made here.
    pub bodies_only: bool,
}

/// Per-pair inputs of the schedulers, index-parallel to the narrow phase's pairs. Only the first
/// [`Self::reached`] entries are this frame's; the accessors answer the no-priority defaults
/// beyond them, so a frame that does not prioritise costs nothing here.
#[derive(Debug, Clone, Default)]
pub struct Priorities {
    weight: Vec<f32>,
    falloff: Vec<f32>,
    scale: Vec<f32>,
    dist: Vec<f32>,
    inner: Vec<bool>,
    /// Pairs prioritised this frame (the rest were cut off by a wall-clock deadline, or the frame
    /// was not prioritised at all).
    pub reached: usize,
    /// Whether this frame's per-body values are complete.
    pub bodies_done: bool,
    body: Vec<BodyView>,
    /// Per body: the model's gap unit per scene unit.
    body_scale: Vec<f32>,
    /// Per body, for schedulers that price pairs themselves: position relative to the volume's
    /// corner (f32: the volume is at most ~60 units wide) and scale times fall-off.
    body_record: Vec<[f32; 4]>,
}

impl Priorities {
    /// Read every buffer back into cache (see [`crate::warm`]).
    pub fn warm(&self) {
        for v in [
            &self.weight,
            &self.falloff,
            &self.scale,
            &self.dist,
            &self.body_scale,
        ] {
            crate::warm::lines(v);
        }
        crate::warm::lines(&self.inner);
        crate::warm::lines(&self.body);
        crate::warm::lines(&self.body_record);
    }

    /// Forget this frame's priorities: every pair reads as not prioritised.
    pub fn clear(&mut self) {
        self.reached = 0;
        self.bodies_done = false;
    }

    /// Per-body records of the last body pass: position relative to the volume corner, and the
    /// body's scale times its fall-off (scale alone with `gaze` off). Empty before the pass.
    #[inline]
    pub fn body_records(&self) -> &[[f32; 4]] {
        if self.bodies_done {
            &self.body_record
        } else {
            &[]
        }
    }

    /// The model's gap unit per scene unit at body `b` (1 before the body pass).
    #[inline]
    pub fn body_scale(&self, b: usize) -> f32 {
        if self.bodies_done {
            self.body_scale[b]
        } else {
            1.0
        }
    }

    /// F of the scheduling model on pair `i`'s untested evidence (body centres): the paper's
    /// priority, higher first; 0 if not prioritised.
    #[inline]
    pub fn weight(&self, i: usize) -> f32 {
        if i < self.reached {
            self.weight[i]
        } else {
            0.0
        }
    }

    /// Eccentricity fall-off F(1, e) at pair `i`'s centre; 1 without a fixation.
    #[inline]
    pub fn falloff(&self, i: usize) -> f32 {
        if i < self.reached {
            self.falloff[i]
        } else {
            1.0
        }
    }

    /// The model's gap unit per scene unit at pair `i` (pixels or degrees per unit length).
    #[inline]
    pub fn scale(&self, i: usize) -> f32 {
        if i < self.reached { self.scale[i] } else { 0.0 }
    }

    /// Centre distance of pair `i` over twice the root radius: 1 is where the root spheres touch.
    #[inline]
    pub fn dist(&self, i: usize) -> f32 {
        if i < self.reached { self.dist[i] } else { 0.0 }
    }

    /// Whether pair `i` is inside the priority-queue eccentricity threshold.
    #[inline]
    pub fn inner(&self, i: usize) -> bool {
        i < self.reached && self.inner[i]
    }
}

/// The constant part of prioritisation: display geometry, model and threshold.
#[derive(Debug, Clone)]
pub struct Prioritiser {
    falloff: Falloff,
    needs: Needs,
    threshold_deg: f64,
    threshold_chord: f64,
    pitch: f64,
    centre: [f64; 2],
    distance: f64,
    /// Pixels per scene unit at depth 1 (the camera's focal length in pixels).
    focal: f64,
    eye: Vec3,
    inv_root_diameter: f32,
}

impl Prioritiser {
    /// For `viewer`, scheduling `model`, a first queue within `threshold_deg`, sphere trees whose
    /// root has radius `root_radius`, and a scheduler that needs `needs`.
    pub fn new(
        viewer: &Viewer,
        model: &crate::perception::PerceptualModel,
        threshold_deg: f64,
        root_radius: f64,
        needs: Needs,
    ) -> Self {
        let d = &viewer.display;
        let half = (0.5 * threshold_deg.clamp(0.0, 180.0)).to_radians();
        Self {
            falloff: Falloff::new(model),
            needs,
            threshold_deg: threshold_deg.clamp(0.0, 180.0),
            threshold_chord: 2.0 * half.sin(),
            pitch: d.pixel_pitch_cm(),
            centre: [0.5 * f64::from(d.width_px), 0.5 * f64::from(d.height_px)],
            distance: d.viewing_distance_cm,
            focal: viewer.focal_px(),
            eye: viewer.eye,
            inv_root_diameter: (0.5 / root_radius) as f32,
        }
    }

    /// Screen position, eye ray and scale of a world point: one division and one square root.
    #[inline]
    fn body_view(&self, p: Vec3) -> BodyView {
        let (dx, dy, s, ray) = self.project(p);
        let px = [self.centre[0] as f32 + dx, self.centre[1] as f32 + dy];
        let scale = match self.falloff.unit() {
            EccentricityUnit::Degrees => self.degree_scale(s, ray),
            EccentricityUnit::Pixels => s as f32,
        };
        BodyView { px, ray, scale }
    }

    /// A world point's offset from the screen centre (pixels), pixels per scene unit at its depth
    /// and its unit eye ray.
    #[inline]
    fn project(&self, p: Vec3) -> (f32, f32, f64, [f32; 3]) {
        let r = p - self.eye;
        let depth = (-r.z).max(1e-9 * (1.0 + r.x.abs() + r.y.abs()));
        let s = self.focal / depth;
        let (dx, dy) = ((r.x * s) as f32, (-r.y * s) as f32);
        let (pitch, dist) = (self.pitch as f32, self.distance as f32);
        let v = [dx * pitch, dy * pitch, dist];
        let inv = 1.0 / (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        (dx, dy, s, [v[0] * inv, v[1] * inv, v[2] * inv])
    }

    /// Degrees of visual angle per scene unit, from [`Self::project`]'s scale and ray: a degree
    /// per pixel shrinks as cos^2 of the angle off the screen's axis.
    #[inline]
    fn degree_scale(&self, s: f64, ray: [f32; 3]) -> f32 {
        s as f32 * (self.pitch as f32 / self.distance as f32) * ray[2] * ray[2] * 57.295_78
    }

    /// [`Self::body_view`]'s scale (degrees unit) and the chord of each body's eye ray to
    /// `fix_ray`, for a block of bodies, written over plain arrays so that it vectorises.
    fn project_block(&self, ps: &[Vec3], fix_ray: [f32; 3], arg: &mut [f32], scale: &mut [f32]) {
        for ((p, a), sc) in ps.iter().zip(arg.iter_mut()).zip(scale.iter_mut()) {
            let (_, _, s, ray) = self.project(*p);
            *sc = self.degree_scale(s, ray);
            *a = chord(ray, fix_ray);
        }
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

    /// Fill `out` for `pairs`. With a fixation (pixels, and its uncertainty in degrees), fall-offs
    /// (and, if needed, weights and the first queue) follow it; without one every fall-off is 1
    /// and no pair is in the first queue. An uncertain fixation schedules everything within its
    /// radius as foveal: eccentricities are reduced by the radius, and the first queue's
    /// threshold grows by it ([`crate::Fixation::uncertainty_deg`]). Checks a wall-clock deadline every 64 pairs and stops when it has passed: pairs not
    /// reached read as unprioritised, so a budget smaller than prioritisation is still held.
    pub fn prioritise(
        &self,
        pairs: &[PairState],
        world: &World,
        viewer: &Viewer,
        fixation: Option<([f64; 2], f64)>,
        out: &mut Priorities,
        meter: &mut Meter<'_>,
    ) {
        let n = pairs.len();
        out.reached = 0;
        out.bodies_done = false;
        for v in [
            &mut out.weight,
            &mut out.falloff,
            &mut out.scale,
            &mut out.dist,
        ] {
            if v.len() < n {
                v.resize(n, 0.0);
            }
        }
        if out.inner.len() < n {
            out.inner.resize(n, false);
        }
        let uncertainty_deg = fixation.map_or(0.0, |(_, u)| u.clamp(0.0, 180.0));
        // The radius in the fall-off's unit, and the first queue's threshold grown by it.
        let widen = match self.falloff.unit() {
            EccentricityUnit::Degrees => uncertainty_deg,
            EccentricityUnit::Pixels => uncertainty_deg * viewer.display.pixels_per_degree(),
        } as f32;
        let threshold_chord = if uncertainty_deg > 0.0 {
            let half = (0.5 * (self.threshold_deg + uncertainty_deg).min(180.0)).to_radians();
            2.0 * half.sin()
        } else {
            self.threshold_chord
        };
        let factor = |x: f32| {
            if widen > 0.0 {
                self.falloff.factor_widened(x, widen)
            } else {
                self.falloff.factor(x)
            }
        };
        let fix = fixation.map(|(f, _)| {
            let px = [f[0] as f32, f[1] as f32];
            let r = viewer.display.eye_ray(f);
            let view = BodyView {
                px,
                ray: [r[0] as f32, r[1] as f32, r[2] as f32],
                scale: 0.0,
            };
            (view, r)
        });
        if self.needs.bodies_only {
            // One pass writing only the records the pricing reads: under a wall-clock budget
            // this is paid from the frame's time, and touching fewer arrays is most of its cost.
            let lo = world.lo;
            out.body_record.clear();
            out.body_scale.clear();
            out.body_record.resize(world.position.len(), [0.0; 4]);
            out.body_scale.resize(world.position.len(), 0.0);
            let (records, scales) = (&mut out.body_record, &mut out.body_scale);
            // In blocks: first the projection of every body of the block (straight-line
            // arithmetic over plain arrays, which the compiler vectorises), then the table
            // lookups. The arithmetic is `body_view` and `arg`'s, operation for operation.
            const BLOCK: usize = 64;
            let mut arg = [0f32; BLOCK];
            let mut scale = [0f32; BLOCK];
            let degrees = self.falloff.unit() == EccentricityUnit::Degrees;
            for ((block, rec), scl) in world
                .position
                .chunks(BLOCK)
                .zip(records.chunks_mut(BLOCK))
                .zip(scales.chunks_mut(BLOCK))
            {
                let m = block.len();
                match &fix {
                    Some((f, _)) if degrees => {
                        self.project_block(block, f.ray, &mut arg[..m], &mut scale[..m]);
                    }
                    _ => {
                        for ((p, a), sc) in block.iter().zip(arg.iter_mut()).zip(scale.iter_mut()) {
                            let v = self.body_view(*p);
                            *a = fix.as_ref().map_or(0.0, |(f, _)| self.arg(&v, f));
                            *sc = v.scale;
                        }
                    }
                }
                let lookups = block.iter().zip(&arg).zip(&scale).zip(rec).zip(scl);
                for ((((p, a), sc), rec), scl) in lookups {
                    let f = if fix.is_some() { factor(*a) } else { 1.0 };
                    let r = (*p - lo).as_vec3();
                    *rec = [r.x, r.y, r.z, sc * f];
                    *scl = *sc;
                }
            }
            out.bodies_done = true;
            return;
        }
        out.body.clear();
        out.body
            .extend(world.position.iter().map(|&p| self.body_view(p)));
        out.body_scale.clear();
        out.body_scale.extend(out.body.iter().map(|v| v.scale));
        if meter.exhausted_by_clock() {
            return;
        }
        out.bodies_done = true;
        let degrees = self.falloff.unit() == EccentricityUnit::Degrees;
        let Priorities {
            weight,
            falloff,
            scale,
            dist,
            inner,
            body,
            reached,
            ..
        } = out;
        for (k, p) in pairs.iter().enumerate() {
            // Sphere-test budgets do not count this work (it tests no spheres).
            if k % 64 == 0 && k > 0 && meter.exhausted_by_clock() {
                return;
            }
            let (a, b) = (p.a as usize, p.b as usize);
            let (pa, pb) = (world.position[a], world.position[b]);
            dist[k] = (pb - pa).as_vec3().length() * self.inv_root_diameter;
            let (va, vb) = (&body[a], &body[b]);
            scale[k] = 0.5 * (va.scale + vb.scale);
            if let Some((f, f_ray)) = &fix {
                // The centre's eye ray, unnormalised: two bodies of one pair are a few degrees
                // apart, and the half-sum's length is off 1 by under 1e-3 of the chord there.
                let e_arg = if degrees {
                    let m = [
                        0.5 * (va.ray[0] + vb.ray[0]) - f.ray[0],
                        0.5 * (va.ray[1] + vb.ray[1]) - f.ray[1],
                        0.5 * (va.ray[2] + vb.ray[2]) - f.ray[2],
                    ];
                    (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt()
                } else {
                    (0.5 * (va.px[0] + vb.px[0]) - f.px[0])
                        .hypot(0.5 * (va.px[1] + vb.px[1]) - f.px[1])
                };
                let fo = factor(e_arg);
                falloff[k] = fo;
                if self.needs.weight {
                    weight[k] = fo * self.falloff.eccentricity(self.arg(va, vb));
                }
                if self.needs.inner {
                    let c = viewer.project((pa + pb) * 0.5);
                    inner[k] = chord64(viewer.display.eye_ray(c), *f_ray) <= threshold_chord;
                }
            } else {
                falloff[k] = 1.0;
                if self.needs.weight {
                    weight[k] = self.falloff.eccentricity(self.arg(va, vb));
                }
                inner[k] = false;
            }
            *reached = k + 1;
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
