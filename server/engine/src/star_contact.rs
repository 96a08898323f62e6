//! Exact contact between two stars: the shape level below the sphere tree's leaves
//! (docs/DESIGN.md "Exact answer").
//!
//! The paper decides a collision on leaf spheres (section 2). They contain the star but overshoot
//! it by up to 0.36R beside the spike tips, so under that definition every bounce happens across a
//! visible gap. Under [`crate::Truth::Shape`] a pair whose leaves overlap is then tested here, on
//! the star itself: a core ball and six cones, each convex, so two stars touch iff some part of
//! one touches some part of the other, and their distance is the least over part pairs.
//!
//! Each part kind has the cheapest exact test there is, as parry does for its convex shapes:
//! - ball against ball: the centre distance;
//! - ball against cone: closed form, because a cone is a solid of revolution: the distance from a
//!   point to it is the distance, in the point's meridian half-plane, to the cone's triangle
//!   (base centre, rim, apex);
//! - cone against cone: GJK on the cones' support mappings, with EPA for the penetration depth
//!   and normal where the cones overlap.
//!
//! The hierarchy reaches the parts that can touch before any exact test runs: a part whose
//! bounding sphere misses the other star's bounding sphere is skipped, a cone pair whose bounding
//! spheres miss or whose enclosing capsules (axis segment plus base radius) miss is skipped, and
//! a cone pair whose extents along the line between their axes' nearest points are apart (a
//! separating plane in closed form) needs no GJK. At first contact only one or two part pairs
//! survive.
//!
//! Everything is in body A's frame, in f64: body B is placed by a [`Pose`], so coordinates are of
//! the order of R wherever the pair is. Touching counts as colliding (closed shapes), with a
//! tolerance of [`TOUCH_TOLERANCE`] times R for the iterative tests.

use glam::{DMat3, DVec3};

use crate::shape::Star;

/// Distances at or below this fraction of R count as touching. GJK and EPA stop within a
/// relative error far below it; the closed forms are exact to rounding.
pub const TOUCH_TOLERANCE: f64 = 1e-9;

/// The penetration depth's tolerance, a fraction of R: EPA stops when its polytope's nearest
/// face is within this of the shapes' true extent along its normal. The depth decides nothing
/// (touching is decided by GJK at [`TOUCH_TOLERANCE`]); it gives the response its normal and the
/// reports their overlap. Asked to the touching tolerance, EPA on the spikes' curved rims ran
/// into its iteration cap on about 1% of the contacts at N = 10,000, at up to half a millisecond
/// each: two thirds of the response's time.
const DEPTH_TOLERANCE: f64 = 1e-7;

/// Iterations after which GJK or EPA stops with what it has (it converges in 5-15 on these
/// shapes; the cap only guards degenerate input).
const MAX_ITERATIONS: usize = 64;

/// Body B's frame expressed in body A's frame: `x_A = rotation * x_B + translation`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// B's axes in A's frame (the columns are B's x, y and z axes).
    pub rotation: DMat3,
    /// B's centre in A's frame.
    pub translation: DVec3,
}

/// How two stars stand, in A's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// The stars touch or overlap.
    Touching {
        /// Contact point: midway between the two surfaces along the normal.
        point: DVec3,
        /// Unit contact normal, from A towards B: moving B along it by `depth` separates them.
        normal: DVec3,
        /// Penetration depth (0 when they just touch).
        depth: f64,
    },
    /// The stars are apart.
    Apart {
        /// The least distance between them (> 0).
        distance: f64,
        /// The point of A nearest B.
        point_a: DVec3,
        /// The point of B nearest A.
        point_b: DVec3,
    },
}

impl Contact {
    /// Whether the stars touch.
    pub fn is_touching(&self) -> bool {
        matches!(self, Self::Touching { .. })
    }

    /// The gap between the two surfaces: 0 when touching.
    pub fn gap(&self) -> f64 {
        match *self {
            Self::Touching { .. } => 0.0,
            Self::Apart { distance, .. } => distance,
        }
    }

    /// Signed distance: the gap when apart, minus the depth when overlapping.
    pub fn signed_distance(&self) -> f64 {
        match *self {
            Self::Touching { depth, .. } => -depth,
            Self::Apart { distance, .. } => distance,
        }
    }

    /// Centre of collision on the shape: the contact point, or the midpoint of the closest
    /// points when apart.
    pub fn centre(&self) -> DVec3 {
        match *self {
            Self::Touching { point, .. } => point,
            Self::Apart {
                point_a, point_b, ..
            } => (point_a + point_b) * 0.5,
        }
    }

    /// Unit normal from A towards B: the contact normal, or the direction from A's closest point
    /// to B's.
    pub fn normal(&self) -> DVec3 {
        match *self {
            Self::Touching { normal, .. } => normal,
            Self::Apart {
                point_a, point_b, ..
            } => (point_b - point_a).normalize_or(DVec3::X),
        }
    }
}

/// Spike axes in a star's own frame, in part order (part `k + 1` is the spike along `AXES[k]`).
const AXES: [DVec3; 6] = [
    DVec3::X,
    DVec3::NEG_X,
    DVec3::Y,
    DVec3::NEG_Y,
    DVec3::Z,
    DVec3::NEG_Z,
];

/// A cone: base disc of `radius` centred at `base`, apex at `base + axis * height`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Cone {
    base: DVec3,
    axis: DVec3,
    height: f64,
    radius: f64,
    /// Length of a generator, hypot(height, radius) (kept: `hypot` is a library call).
    slant: f64,
}

impl Cone {
    #[inline]
    fn apex(&self) -> DVec3 {
        self.base + self.axis * self.height
    }

    /// A point of the cone farthest along `d`: the apex, or the rim point towards `d`.
    #[inline]
    fn support(&self, d: DVec3) -> DVec3 {
        let along = d.dot(self.axis);
        // Projected twice: for d nearly along the axis (the base disc's face) one pass leaves
        // an axial residue of rounding as large as the perpendicular part itself, and the rim
        // point built from it would lie off the disc, outside the cone, so that GJK could
        // report a distance below the true one. The second pass puts it back on the disc.
        let perp = d - self.axis * along;
        let perp = perp - self.axis * perp.dot(self.axis);
        let pl = perp.length();
        // The apex wins iff h (d·axis) >= r |d_perp| (both measured from the base centre).
        if self.height * along >= self.radius * pl {
            self.apex()
        } else if pl > 0.0 {
            self.base + perp * (self.radius / pl)
        } else {
            self.base
        }
    }
}

/// A star's dimensions and the bounds derived from them, for the tests of one scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StarGeometry {
    /// Bounding radius R (the spike apexes).
    pub radius: f64,
    /// Core ball radius.
    pub core: f64,
    /// Spike base disc radius.
    pub base: f64,
    /// Centre of a spike's smallest bounding sphere, along its axis from the star's centre.
    bound_offset: f64,
    /// Radius of a spike's smallest bounding sphere.
    bound_radius: f64,
    /// Touching tolerance in scene units.
    eps: f64,
    /// A spike's generator length, hypot(R, b).
    slant: f64,
}

impl StarGeometry {
    /// The geometry of `star`.
    pub fn new(star: Star) -> Self {
        let (h, b) = (star.radius, star.spike_base_radius);
        // The smallest sphere through the apex and the base rim, centred on the axis, if its
        // centre lies above the base; else the base disc's own sphere.
        let s0 = (h * h - b * b) / (2.0 * h);
        let (bound_offset, bound_radius) = if s0 > 0.0 { (s0, h - s0) } else { (0.0, b) };
        Self {
            radius: star.radius,
            core: star.core_radius,
            base: b,
            bound_offset,
            bound_radius,
            eps: TOUCH_TOLERANCE * star.radius,
            slant: h.hypot(b),
        }
    }

    /// Spike `k` of a star at `centre` whose spike axes are `axes`.
    #[inline]
    fn cone(&self, centre: DVec3, axis: DVec3) -> Cone {
        Cone {
            base: centre,
            axis,
            height: self.radius,
            radius: self.base,
            slant: self.slant,
        }
    }

    /// Whether star B at `pose` touches star A at the origin (A's frame).
    ///
    /// Early-outs in order of cost: the two bounding spheres, the cores, core against spike in
    /// closed form, then spike against spike by GJK where bounding spheres and capsules allow.
    pub fn intersects(&self, pose: &Pose) -> bool {
        self.intersects_or_bound(pose).is_none()
    }

    /// [`Self::intersects`], and when the stars are apart a proven lower bound on their
    /// distance (`Some(bound)`, `bound >= 0`): the least, over the part pairs, of what each test
    /// proved, whether the exact distance of a closed form, GJK's separating plane or a bounding
    /// sphere's or capsule's clearance. `None` when they touch. A pair that keeps this bound
    /// across frames is apart for as long as its relative motion stays below it.
    pub fn intersects_or_bound(&self, pose: &Pose) -> Option<f64> {
        let t = pose.translation;
        let d2 = t.length_squared();
        let reach = 2.0 * self.radius + self.eps;
        if d2 > reach * reach {
            return Some(d2.sqrt() - 2.0 * self.radius);
        }
        let core_reach = 2.0 * self.core + self.eps;
        if d2 <= core_reach * core_reach {
            return None;
        }
        let d = d2.sqrt();
        // The star's convex hull is the octahedron of its six apexes (the core, 0.3R, and the
        // spikes' base discs, 0.25R, lie inside its inradius of R / sqrt 3), whose support along
        // a unit direction n is R |n|_inf in the star's frame. Projected on the centre line the
        // two hulls are apart when d exceeds the sum of their supports.
        let u = t / d;
        let ub = pose.rotation.transpose() * u;
        let plane = d - self.radius * (u.abs().max_element() + ub.abs().max_element());
        if plane > self.eps {
            return Some(plane);
        }
        let mut lower = d - 2.0 * self.core;
        // Lower the bound to a part's clearance sqrt(dist2) - r, taking the root only where it
        // can lower it: most parts are far, and a root per part was most of the test's time.
        let relax = |lower: &mut f64, dist2: f64, r: f64| {
            let reach = *lower + r;
            if reach <= 0.0 || dist2 < reach * reach {
                *lower = lower.min(dist2.sqrt() - r);
            }
        };
        let axes_b = b_axes(pose);
        let (rb, off) = (self.bound_radius, self.bound_offset);
        // Spikes of A against B's core, and of B against A's core.
        let core_bound = rb + self.core + self.eps;
        for k in 0..6 {
            let ca = AXES[k] * off;
            let da = (ca - t).length_squared();
            if da <= core_bound * core_bound {
                let d = point_cone(t, &self.cone(DVec3::ZERO, AXES[k])).0 - self.core;
                if d <= self.eps {
                    return None;
                }
                lower = lower.min(d);
            } else {
                relax(&mut lower, da, rb + self.core);
            }
            let cb = t + axes_b[k] * off;
            let db = cb.length_squared();
            if db <= core_bound * core_bound {
                let d = point_cone(DVec3::ZERO, &self.cone(t, axes_b[k])).0 - self.core;
                if d <= self.eps {
                    return None;
                }
                lower = lower.min(d);
            } else {
                relax(&mut lower, db, rb + self.core);
            }
        }
        // Spikes against spikes: only those whose bounding sphere reaches the other star.
        let star_bound = rb + self.radius + self.eps;
        let pair_bound = 2.0 * rb + self.eps;
        let capsule = 2.0 * self.base + self.eps;
        let mut near_b = [DVec3::ZERO; 6];
        let mut nb = 0;
        for axis in axes_b {
            let cb = t + axis * off;
            let db = cb.length_squared();
            if db <= star_bound * star_bound {
                near_b[nb] = axis;
                nb += 1;
            } else {
                // This spike is farther from all of A than its bounding sphere allows.
                relax(&mut lower, db, rb + self.radius);
            }
        }
        for axis_a in AXES {
            let ca = axis_a * off;
            let da = (ca - t).length_squared();
            if da > star_bound * star_bound {
                relax(&mut lower, da, rb + self.radius);
                continue;
            }
            for &axis_b in &near_b[..nb] {
                let cb = t + axis_b * off;
                let dab = (ca - cb).length_squared();
                if dab > pair_bound * pair_bound {
                    relax(&mut lower, dab, 2.0 * rb);
                    continue;
                }
                let (pa, pb) = (axis_a * self.radius, t + axis_b * self.radius);
                let offset = segment_offset(DVec3::ZERO, pa, t, pb);
                let seg = offset.length_squared();
                if seg > capsule * capsule {
                    relax(&mut lower, seg, 2.0 * self.base);
                    continue;
                }
                // The line joining the axes' nearest points nearly separates two thin cones
                // that do not touch: their extents along it, in closed form, often prove them
                // apart at the cost of two support values.
                if seg > 0.0 {
                    let gap = self.axis_gap(axis_a, t, axis_b, offset / -seg.sqrt());
                    if gap > self.eps {
                        lower = lower.min(gap);
                        continue;
                    }
                }
                // Tighter: each spike is inside two capsules, its base half (radius b) and its
                // tip half (radius b / 2). Tip against tip or flank is the common near miss, and
                // this settles most of them without GJK.
                let split = self.split_capsules(axis_a, t, axis_b);
                if split > self.eps {
                    lower = lower.min(split);
                    continue;
                }
                let (ka, kb) = (self.cone(DVec3::ZERO, axis_a), self.cone(t, axis_b));
                let g = gjk(&ka, &kb, self.eps, true);
                if g.touching {
                    return None;
                }
                lower = lower.min(g.lower);
            }
        }
        Some(lower.max(0.0))
    }

    /// How far apart A's spike along `axis_a` and B's spike along `axis_b` (B centred at `t`)
    /// are along the unit direction `u` (from A towards B): B's least extent along `u` less A's
    /// greatest. Positive, it is a lower bound on their distance (a separating plane). A
    /// cone's extent along `u` is its base centre's plus the larger of its apex's,
    /// `h (u . axis)`, and its rim's, `b |u - axis (u . axis)|`.
    #[inline]
    fn axis_gap(&self, axis_a: DVec3, t: DVec3, axis_b: DVec3, u: DVec3) -> f64 {
        let (h, b) = (self.radius, self.base);
        let (ua, ub) = (u.dot(axis_a), u.dot(axis_b));
        let reach_a = (h * ua).max(b * (u - axis_a * ua).length());
        let reach_b = (-h * ub).max(b * (u - axis_b * ub).length());
        u.dot(t) - reach_b - reach_a
    }

    /// A lower bound on the distance between A's spike along `axis_a` and B's spike along
    /// `axis_b` (B centred at `t`): each spike lies in the union of two capsules, the axis's base
    /// half with radius b and its tip half with radius b / 2 (the cone's radius there is at most
    /// that), so the least separation over the four capsule pairs bounds the spikes'.
    #[inline]
    fn split_capsules(&self, axis_a: DVec3, t: DVec3, axis_b: DVec3) -> f64 {
        let h = self.radius;
        let (ma, ea) = (axis_a * (0.5 * h), axis_a * h);
        let (mb, eb) = (t + axis_b * (0.5 * h), t + axis_b * h);
        let pieces_a = [(DVec3::ZERO, ma, self.base), (ma, ea, 0.5 * self.base)];
        let pieces_b = [(t, mb, self.base), (mb, eb, 0.5 * self.base)];
        let mut least = f64::INFINITY;
        for (a0, a1, ra) in pieces_a {
            for (b0, b1, rb) in pieces_b {
                let d = segment_distance_squared(a0, a1, b0, b1).sqrt() - ra - rb;
                least = least.min(d);
            }
        }
        least
    }

    /// How star B at `pose` stands against star A at the origin: the deepest contact of any part
    /// pair when they touch, else the least distance and its closest points.
    ///
    /// Part pairs are taken in order of their bounding spheres' separation, a lower bound on
    /// their signed distance, and the search stops when that bound cannot beat the best found.
    pub fn contact(&self, pose: &Pose) -> Contact {
        if self.intersects(pose) {
            return self.contact_of_touching(pose);
        }
        self.nearest(pose.translation, &b_axes(pose))
    }

    /// [`Self::contact`] of a pose that [`Self::intersects`] has already found touching: the
    /// same contact, without that test again. The response's real collisions are such poses
    /// (the narrow phase settled each by that very test, on the same pose), and the test was
    /// a sixth of a real collision's contact: 11.9 against 10.0 µs a contact, medians of 15
    /// interleaved rounds over the 541 real collisions of a 10,000-body frame.
    pub fn contact_of_touching(&self, pose: &Pose) -> Contact {
        let t = pose.translation;
        let axes_b = b_axes(pose);
        // Touching stars: the deepest part pair is one that touches, so only the part pairs
        // that can touch are ordered, each is first tested yes or no, and only the touching
        // ones pay for a depth (EPA for two spikes). A part pair that does not touch has a
        // signed distance of at least 0 and cannot be the deepest.
        let (order, len) = self.part_order(t, &axes_b, self.eps);
        if let Some(c) = self.deepest(t, &axes_b, &order[..len]) {
            return c;
        }
        self.nearest(t, &axes_b)
    }

    /// The nearest part pair's contact (the least signed distance): the part pairs in order of
    /// their lower bounds, until a bound cannot beat the best found.
    fn nearest(&self, t: DVec3, axes_b: &[DVec3; 6]) -> Contact {
        let (order, len) = self.part_order(t, axes_b, f64::INFINITY);
        let mut best: Option<(f64, Contact)> = None;
        for &(lower, i, j) in &order[..len] {
            if best.is_some_and(|(s, _)| lower >= s) {
                break;
            }
            let c = self.part_contact(t, axes_b, usize::from(i), usize::from(j));
            let s = c.signed_distance();
            if best.is_none_or(|(b, _)| s < b) {
                best = Some((s, c));
            }
        }
        match best {
            Some((_, c)) => c,
            None => unreachable!("49 part pairs, the first always evaluated"),
        }
    }

    /// The part pairs (A's part, B's part: 0 the core, 1..=6 the spikes) whose lower bound on
    /// the signed distance is at most `cut`, in increasing order of that bound (then by parts),
    /// and how many there are. The bound is the parts' bounding spheres' separation, and for
    /// two spikes the separation of the capsules around them (axis segment plus base radius),
    /// which is much tighter.
    fn part_order(&self, t: DVec3, axes_b: &[DVec3; 6], cut: f64) -> ([(f64, u8, u8); 49], usize) {
        let off = self.bound_offset;
        let bound = |centre: DVec3, axes: &[DVec3; 6], part: usize| -> (DVec3, f64) {
            if part == 0 {
                (centre, self.core)
            } else {
                (centre + axes[part - 1] * off, self.bound_radius)
            }
        };
        let mut order = [(0.0f64, 0u8, 0u8); 49];
        let mut len = 0;
        for i in 0..7 {
            let (ca, ra) = bound(DVec3::ZERO, &AXES, i);
            for j in 0..7 {
                let (cb, rb) = bound(t, axes_b, j);
                let mut lower = (cb - ca).length() - ra - rb;
                if i > 0 && j > 0 && lower < self.radius && lower <= cut {
                    let (pa, pb) = (AXES[i - 1] * self.radius, t + axes_b[j - 1] * self.radius);
                    let capsules =
                        segment_distance_squared(DVec3::ZERO, pa, t, pb).sqrt() - 2.0 * self.base;
                    lower = lower.max(capsules);
                }
                if lower <= cut {
                    order[len] = (lower, i as u8, j as u8);
                    len += 1;
                }
            }
        }
        order[..len].sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then((x.1, x.2).cmp(&(y.1, y.2))));
        (order, len)
    }

    /// The deepest contact among the part pairs of `order` (sorted by their lower bounds) that
    /// touch, the first of equals; `None` if none does.
    fn deepest(&self, t: DVec3, axes_b: &[DVec3; 6], order: &[(f64, u8, u8)]) -> Option<Contact> {
        let mut best: Option<(f64, Contact)> = None;
        for &(lower, i, j) in order {
            // Sorted: no later pair can touch, or be deeper than the best found.
            if lower > self.eps || best.is_some_and(|(s, _)| lower >= s) {
                break;
            }
            let (i, j) = (usize::from(i), usize::from(j));
            let c = if i > 0 && j > 0 {
                let (axis_a, axis_b) = (AXES[i - 1], axes_b[j - 1]);
                if self.split_capsules(axis_a, t, axis_b) > self.eps {
                    continue;
                }
                let (ka, kb) = (self.cone(DVec3::ZERO, axis_a), self.cone(t, axis_b));
                // A yes-or-no search that finds the cones touching has walked exactly the path
                // of a full one (it differs only in stopping early when apart): its simplex
                // goes straight to EPA.
                let g = gjk(&ka, &kb, self.eps, true);
                if !g.touching {
                    continue;
                }
                cones_from(&ka, &kb, &g, self.eps)
            } else {
                self.part_contact(t, axes_b, i, j)
            };
            if !c.is_touching() {
                continue;
            }
            let s = c.signed_distance();
            if best.is_none_or(|(b, _)| s < b) {
                best = Some((s, c));
            }
        }
        best.map(|(_, c)| c)
    }

    /// Contact of A's part `i` with B's part `j` (0 the core, 1..=6 the spikes).
    fn part_contact(&self, t: DVec3, axes_b: &[DVec3; 6], i: usize, j: usize) -> Contact {
        match (i, j) {
            (0, 0) => balls(DVec3::ZERO, t, self.core, self.eps),
            (0, j) => flip(ball_cone(
                DVec3::ZERO,
                self.core,
                &self.cone(t, axes_b[j - 1]),
                self.eps,
            )),
            (i, 0) => ball_cone(t, self.core, &self.cone(DVec3::ZERO, AXES[i - 1]), self.eps),
            (i, j) => cones(
                &self.cone(DVec3::ZERO, AXES[i - 1]),
                &self.cone(t, axes_b[j - 1]),
                self.eps,
            ),
        }
    }
}

/// B's spike axes in A's frame, in part order.
#[inline]
fn b_axes(pose: &Pose) -> [DVec3; 6] {
    let m = pose.rotation;
    [
        m.x_axis, -m.x_axis, m.y_axis, -m.y_axis, m.z_axis, -m.z_axis,
    ]
}

/// A contact seen from the other side: A and B swapped.
fn flip(c: Contact) -> Contact {
    match c {
        Contact::Touching {
            point,
            normal,
            depth,
        } => Contact::Touching {
            point,
            normal: -normal,
            depth,
        },
        Contact::Apart {
            distance,
            point_a,
            point_b,
        } => Contact::Apart {
            distance,
            point_a: point_b,
            point_b: point_a,
        },
    }
}

/// Two balls of radius `r` at `a` and `b`.
fn balls(a: DVec3, b: DVec3, r: f64, eps: f64) -> Contact {
    let d = b - a;
    let len = d.length();
    // Coincident centres: any normal separates them equally well; +x is the deterministic pick.
    let n = unit_or(d, DVec3::X);
    let s = len - 2.0 * r;
    if s <= eps {
        Contact::Touching {
            point: a + n * (0.5 * len),
            normal: n,
            depth: (-s).max(0.0),
        }
    } else {
        Contact::Apart {
            distance: s,
            point_a: a + n * r,
            point_b: b - n * r,
        }
    }
}

/// A cone (part of A) against a ball of radius `r` at `centre` (part of B).
fn ball_cone(centre: DVec3, r: f64, cone: &Cone, eps: f64) -> Contact {
    let (sd, on_cone, n) = point_cone(centre, cone);
    let s = sd - r;
    if s <= eps {
        let on_ball = centre - n * r;
        Contact::Touching {
            point: (on_cone + on_ball) * 0.5,
            normal: n,
            depth: (-s).max(0.0),
        }
    } else {
        Contact::Apart {
            distance: s,
            point_a: on_cone,
            point_b: centre - n * r,
        }
    }
}

/// `d` scaled to unit length, or `fallback` for a zero vector; scaled by its largest component
/// first, so that a vector whose squared length underflows still gets a unit direction.
#[inline]
fn unit_or(d: DVec3, fallback: DVec3) -> DVec3 {
    let m = d.abs().max_element();
    if m > 0.0 && m.is_finite() {
        let u = d / m;
        u / u.length()
    } else {
        fallback
    }
}

/// Any unit vector perpendicular to unit `a` (deterministic).
#[inline]
fn perpendicular(a: DVec3) -> DVec3 {
    a.any_orthonormal_vector()
}

/// Signed distance from `p` to `cone` (negative inside), the nearest point of its surface, and
/// the unit outward normal there (from the cone towards `p` when outside).
///
/// The cone is a solid of revolution, so the question is two-dimensional: in the half-plane
/// through the axis and `p`, with `t` along the axis and `rho` away from it, the cone is the
/// triangle (0, 0), (0, b), (h, 0); the axis edge is inside the solid, not on its surface.
fn point_cone(p: DVec3, cone: &Cone) -> (f64, DVec3, DVec3) {
    let (h, b) = (cone.height, cone.radius);
    let u = p - cone.base;
    let t = u.dot(cone.axis);
    let radial = u - cone.axis * t;
    // Off the axis by a hair, the subtraction leaves an axial part of the order of the rounding:
    // take it out again before the radial direction is normalised.
    let radial = radial - cone.axis * radial.dot(cone.axis);
    let rho = radial.length();
    let e = unit_or(radial, perpendicular(cone.axis));
    let l = cone.slant;
    // Signed distance to the slant side's line, positive outside.
    let slant = (b * t + h * rho - b * h) / l;
    let slant_normal = (cone.axis * b + e * h) / l;
    if t >= 0.0 && slant <= 0.0 {
        // Inside: the nearer of the base plane and the slant side (a convex polygon's interior
        // point is nearest its boundary on the edge whose line is nearest).
        return if t <= -slant {
            (-t, p - cone.axis * t, -cone.axis)
        } else {
            (slant, p - slant_normal * slant, slant_normal)
        };
    }
    // Outside: the nearer of the base segment (0, 0)-(0, b) and the slant segment (0, b)-(h, 0).
    let base_pt = (0.0, rho.clamp(0.0, b));
    let s = ((t * h - (rho - b) * b) / (l * l)).clamp(0.0, 1.0);
    let slant_pt = (s * h, b - s * b);
    let d2 = |q: (f64, f64)| (t - q.0).powi(2) + (rho - q.1).powi(2);
    let (tc, rc) = if d2(base_pt) <= d2(slant_pt) {
        base_pt
    } else {
        slant_pt
    };
    let q = cone.base + cone.axis * tc + e * rc;
    let dist = d2((tc, rc)).sqrt();
    let n = if dist > 0.0 {
        unit_or(p - q, slant_normal)
    } else if tc <= 0.0 && rc < b {
        -cone.axis
    } else {
        slant_normal
    };
    (dist, q, n)
}

/// Squared distance between segments `p0`-`p1` and `q0`-`q1` (closed form, clamped).
#[inline]
fn segment_distance_squared(p0: DVec3, p1: DVec3, q0: DVec3, q1: DVec3) -> f64 {
    segment_offset(p0, p1, q0, q1).length_squared()
}

/// The nearest point of segment `p0`-`p1` to segment `q0`-`q1` less the nearest point of the
/// latter (closed form, clamped).
#[inline]
fn segment_offset(p0: DVec3, p1: DVec3, q0: DVec3, q1: DVec3) -> DVec3 {
    let d1 = p1 - p0;
    let d2 = q1 - q0;
    let r = p0 - q0;
    let a = d1.length_squared();
    let e = d2.length_squared();
    let f = d2.dot(r);
    let c = d1.dot(r);
    let b = d1.dot(d2);
    let denom = a * e - b * b;
    let mut s = if denom > 1e-300 {
        ((b * f - c * e) / denom).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let mut tt = (b * s + f) / e;
    if tt < 0.0 {
        tt = 0.0;
        s = (-c / a).clamp(0.0, 1.0);
    } else if tt > 1.0 {
        tt = 1.0;
        s = ((b - c) / a).clamp(0.0, 1.0);
    }
    (p0 + d1 * s) - (q0 + d2 * tt)
}

/// A vertex of the Minkowski difference A - B, with the points of A and B it came from.
#[derive(Debug, Clone, Copy, Default)]
struct Vertex {
    w: DVec3,
    a: DVec3,
    b: DVec3,
}

#[inline]
fn support(ka: &Cone, kb: &Cone, d: DVec3) -> Vertex {
    let a = ka.support(d);
    let b = kb.support(-d);
    Vertex { w: a - b, a, b }
}

/// What GJK found.
#[derive(Debug, Clone, Copy)]
struct Gjk {
    /// The cones touch (distance within the tolerance, or the origin enclosed).
    touching: bool,
    /// Closest point of A - B to the origin (meaningful when apart).
    v: DVec3,
    /// The simplex and its barycentric weights.
    simplex: [Vertex; 4],
    weights: [f64; 4],
    len: usize,
    /// A proven lower bound on the distance when apart (0 when touching).
    lower: f64,
}

/// GJK distance between two cones. With `boolean`, stops as soon as a separating axis is found.
fn gjk(ka: &Cone, kb: &Cone, eps: f64, boolean: bool) -> Gjk {
    let mut d = kb.base - ka.base;
    if d.length_squared() == 0.0 {
        d = DVec3::X;
    }
    let first = support(ka, kb, -d);
    let mut g = Gjk {
        touching: false,
        v: first.w,
        simplex: [
            first,
            Vertex::default(),
            Vertex::default(),
            Vertex::default(),
        ],
        weights: [1.0, 0.0, 0.0, 0.0],
        len: 1,
        lower: 0.0,
    };
    for _ in 0..MAX_ITERATIONS {
        let v = g.v;
        let vv = v.length_squared();
        if vv <= eps * eps {
            g.touching = true;
            return g;
        }
        let w = support(ka, kb, -v);
        let vw = v.dot(w.w);
        // The plane through w normal to v bounds A - B away from the origin: a distance of at
        // least vw / |v| is proven.
        if boolean && vw > eps * vv.sqrt() {
            g.lower = vw / vv.sqrt();
            return g;
        }
        // Converged when the proven lower bound vw / |v| is within 1e-9 of the upper bound |v|,
        // relatively or in absolute terms (the touching tolerance): on the cones' curved rims
        // GJK converges only linearly, and 1e-12 took tens of iterations more. Stalled when the
        // new vertex is (to 1e-12 R) one the simplex has: no progress is possible.
        let stall = 1e-3 * eps;
        let stalled = g.simplex[..g.len]
            .iter()
            .any(|s| (s.w - w.w).length_squared() <= stall * stall);
        if vv - vw <= (1e-9 * vv).max(eps * vv.sqrt()) || stalled {
            // A search that stalls with its bound well below zero (the plane through w does
            // not separate by 100 tolerances) stopped short of the nearest point: such a pair
            // is not proven apart and counts as touching. Otherwise |v| decides, within the
            // grazing band of a few 1e-7 R where GJK's arithmetic on curved rims is exact no
            // further.
            let lower = vw / vv.sqrt();
            g.touching = vv.sqrt() <= eps || (stalled && lower < -100.0 * eps);
            g.lower = lower.max(0.0);
            return g;
        }
        g.simplex[g.len] = w;
        g.len += 1;
        if !reduce(&mut g) {
            g.touching = true;
            return g;
        }
    }
    // Out of iterations: as for a stall.
    let w = support(ka, kb, -g.v);
    let lower = g.v.dot(w.w) / g.v.length().max(f64::MIN_POSITIVE);
    g.touching = g.v.length() <= eps || lower < -100.0 * eps;
    g.lower = lower.max(0.0);
    g
}

/// Replace the simplex by the smallest face of it that holds its point nearest the origin, with
/// that point's barycentric weights. Returns false when the simplex encloses the origin.
fn reduce(g: &mut Gjk) -> bool {
    let s = g.simplex;
    match g.len {
        2 => {
            set(g, &s, &closest_segment(s[0].w, s[1].w));
            true
        }
        3 => {
            set(g, &s, &closest_triangle([s[0].w, s[1].w, s[2].w]));
            true
        }
        4 => match closest_tetrahedron([s[0].w, s[1].w, s[2].w, s[3].w]) {
            Some(c) => {
                set(g, &s, &c);
                true
            }
            None => false,
        },
        _ => true,
    }
}

fn set(g: &mut Gjk, s: &[Vertex; 4], c: &Closest) {
    for k in 0..c.len {
        g.simplex[k] = s[c.idx[k]];
        g.weights[k] = c.w[k];
    }
    g.len = c.len;
    g.v = c.v;
}

/// The point of a simplex nearest the origin: the face that holds it (`len` vertex indices) and
/// its barycentric weights on that face.
#[derive(Debug, Clone, Copy)]
struct Closest {
    v: DVec3,
    len: usize,
    idx: [usize; 3],
    w: [f64; 3],
}

impl Closest {
    #[inline]
    fn vertex(v: DVec3, i: usize) -> Self {
        Self {
            v,
            len: 1,
            idx: [i, 0, 0],
            w: [1.0, 0.0, 0.0],
        }
    }

    #[inline]
    fn edge(v: DVec3, i: usize, j: usize, t: f64) -> Self {
        Self {
            v,
            len: 2,
            idx: [i, j, 0],
            w: [1.0 - t, t, 0.0],
        }
    }
}

/// Point of segment `a`-`b` nearest the origin.
fn closest_segment(a: DVec3, b: DVec3) -> Closest {
    let ab = b - a;
    let den = ab.length_squared();
    let t = if den > 0.0 { -a.dot(ab) / den } else { 0.0 };
    if t <= 0.0 {
        Closest::vertex(a, 0)
    } else if t >= 1.0 {
        Closest::vertex(b, 1)
    } else {
        Closest::edge(a + ab * t, 0, 1, t)
    }
}

/// Point of triangle `p` nearest the origin, by Voronoi regions (Ericson, Real-Time Collision
/// Detection, 5.1.5).
fn closest_triangle(p: [DVec3; 3]) -> Closest {
    let [a, b, c] = p;
    let (ab, ac) = (b - a, c - a);
    let d1 = ab.dot(-a);
    let d2 = ac.dot(-a);
    if d1 <= 0.0 && d2 <= 0.0 {
        return Closest::vertex(a, 0);
    }
    let d3 = ab.dot(-b);
    let d4 = ac.dot(-b);
    if d3 >= 0.0 && d4 <= d3 {
        return Closest::vertex(b, 1);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return Closest::edge(a + ab * v, 0, 1, v);
    }
    let d5 = ab.dot(-c);
    let d6 = ac.dot(-c);
    if d6 >= 0.0 && d5 <= d6 {
        return Closest::vertex(c, 2);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return Closest::edge(a + ac * w, 0, 2, w);
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return Closest::edge(b + (c - b) * w, 1, 2, w);
    }
    let sum = va + vb + vc;
    if sum.abs() <= f64::MIN_POSITIVE {
        // A degenerate (zero-area) triangle: its nearest edge.
        return closest_segment(a, b);
    }
    let denom = 1.0 / sum;
    let (v, w) = (vb * denom, vc * denom);
    Closest {
        v: a + ab * v + ac * w,
        len: 3,
        idx: [0, 1, 2],
        w: [1.0 - v - w, v, w],
    }
}

/// Point of tetrahedron `p` nearest the origin, or `None` if it encloses the origin.
fn closest_tetrahedron(p: [DVec3; 4]) -> Option<Closest> {
    const FACES: [[usize; 4]; 4] = [[0, 1, 2, 3], [0, 2, 3, 1], [0, 3, 1, 2], [1, 3, 2, 0]];
    let volume = (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0]));
    let scale = (p[1] - p[0]).length() * (p[2] - p[0]).length() * (p[3] - p[0]).length();
    // Nearly flat, its faces' signs cannot be trusted to enclose the origin: take the nearest
    // face instead (an origin truly on it is then at distance 0, touching next iteration).
    let flat = volume.abs() <= 1e-9 * scale;
    let mut best: Option<Closest> = None;
    for f in FACES {
        let (a, b, c, d) = (p[f[0]], p[f[1]], p[f[2]], p[f[3]]);
        let n = (b - a).cross(c - a);
        // The origin lies beyond this face (on the side away from the fourth vertex).
        let outside = flat || (-a).dot(n) * (d - a).dot(n) < 0.0;
        if !outside {
            continue;
        }
        let mut c = closest_triangle([a, b, c]);
        if best.is_none_or(|b| c.v.length_squared() < b.v.length_squared()) {
            for k in 0..c.len {
                c.idx[k] = f[c.idx[k]];
            }
            best = Some(c);
        }
    }
    best
}

/// Contact of two cones (A's, B's): GJK for their distance, EPA for their penetration.
fn cones(ka: &Cone, kb: &Cone, eps: f64) -> Contact {
    cones_from(ka, kb, &gjk(ka, kb, eps, false), eps)
}

/// [`cones`] from GJK's result `g` on the two cones.
fn cones_from(ka: &Cone, kb: &Cone, g: &Gjk, eps: f64) -> Contact {
    let point = |g: &Gjk, pick: fn(&Vertex) -> DVec3| -> DVec3 {
        (0..g.len).map(|k| pick(&g.simplex[k]) * g.weights[k]).sum()
    };
    if !g.touching {
        return Contact::Apart {
            distance: g.v.length(),
            point_a: point(g, |s| s.a),
            point_b: point(g, |s| s.b),
        };
    }
    if g.len == 4
        && let Some(c) = epa(ka, kb, &g.simplex, eps)
    {
        return c;
    }
    // Touching within the tolerance (or a flat simplex): depth 0 at the nearest points, the
    // normal along the centre line of the two cones' bounding segments as a last resort.
    let (pa, pb) = if g.len < 4 {
        (point(g, |s| s.a), point(g, |s| s.b))
    } else {
        (
            ka.base + ka.axis * (0.5 * ka.height),
            kb.base + kb.axis * (0.5 * kb.height),
        )
    };
    let centre_line = unit_or(kb.base - ka.base, DVec3::X);
    let normal = if g.len < 4 {
        unit_or(-g.v, centre_line)
    } else {
        centre_line
    };
    Contact::Touching {
        point: (pa + pb) * 0.5,
        normal,
        depth: 0.0,
    }
}

/// Expanding polytope: the penetration depth and normal of two overlapping cones from GJK's
/// enclosing tetrahedron. `None` if the polytope degenerates.
fn epa(ka: &Cone, kb: &Cone, start: &[Vertex; 4], eps: f64) -> Option<Contact> {
    let mut verts: Vec<Vertex> = start.to_vec();
    // Faces with outward normals (the tetrahedron's orientation fixed first), each with its
    // plane computed once, when it is made: a polytope on the cones' curved rims grows to about
    // a hundred faces, and each iteration reads every face's plane twice.
    let mut faces: Vec<Face> = Vec::with_capacity(64);
    let centroid = verts.iter().map(|v| v.w).sum::<DVec3>() * 0.25;
    for f in [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]] {
        let n = (verts[f[1]].w - verts[f[0]].w).cross(verts[f[2]].w - verts[f[0]].w);
        let f = if n.dot(verts[f[0]].w - centroid) < 0.0 {
            [f[0], f[2], f[1]]
        } else {
            f
        };
        faces.push(Face::new(&verts, f)?);
    }
    let mut kept: Vec<Face> = Vec::with_capacity(64);
    let tolerance = eps * (DEPTH_TOLERANCE / TOUCH_TOLERANCE);
    let mut horizon: Vec<[usize; 2]> = Vec::new();
    for _ in 0..MAX_ITERATIONS {
        let k = nearest_face(&faces);
        let (n, d) = (faces[k].normal, faces[k].distance);
        let w = support(ka, kb, n);
        if w.w.dot(n) - d <= tolerance {
            return Some(face_contact(&verts, &faces[k]));
        }
        // Remove every face that sees w; the horizon's edges, each met once, bound the hole.
        horizon.clear();
        kept.clear();
        for f in &faces {
            if f.normal.dot(w.w) - f.distance > 0.0 {
                let f = f.idx;
                for e in [[f[0], f[1]], [f[1], f[2]], [f[2], f[0]]] {
                    if let Some(pos) = horizon.iter().position(|h| *h == [e[1], e[0]]) {
                        horizon.swap_remove(pos);
                    } else {
                        horizon.push(e);
                    }
                }
            } else {
                kept.push(*f);
            }
        }
        if horizon.is_empty() {
            return Some(face_contact(&verts, &faces[k]));
        }
        let wi = verts.len();
        verts.push(w);
        for e in &horizon {
            kept.push(Face::new(&verts, [e[0], e[1], wi])?);
        }
        std::mem::swap(&mut faces, &mut kept);
    }
    // Not converged within the cap: the nearest face so far is within the last improvement.
    let k = nearest_face(&faces);
    Some(face_contact(&verts, &faces[k]))
}

/// A face of EPA's polytope: its vertices (counter-clockwise seen from outside), outward unit
/// normal and distance from the origin.
#[derive(Clone, Copy)]
struct Face {
    idx: [usize; 3],
    normal: DVec3,
    distance: f64,
}

impl Face {
    /// The face on vertices `f`; `None` if it is degenerate.
    fn new(verts: &[Vertex], f: [usize; 3]) -> Option<Self> {
        let n = (verts[f[1]].w - verts[f[0]].w).cross(verts[f[2]].w - verts[f[0]].w);
        let n = n.try_normalize()?;
        Some(Face {
            idx: f,
            normal: n,
            distance: n.dot(verts[f[0]].w),
        })
    }
}

/// The index of the polytope's face nearest the origin (the first of equals). The polytope
/// always has faces: it starts with four and each step replaces those it removes.
fn nearest_face(faces: &[Face]) -> usize {
    let mut k = 0;
    for (i, f) in faces.iter().enumerate().skip(1) {
        if f.distance < faces[k].distance {
            k = i;
        }
    }
    k
}

/// The contact given by EPA's nearest face: the origin's projection `n d` on it, in barycentric
/// weights, gives the two witness points.
fn face_contact(verts: &[Vertex], face: &Face) -> Contact {
    let (f, n, d) = (face.idx, face.normal, face.distance);
    let (a, b, c) = (verts[f[0]], verts[f[1]], verts[f[2]]);
    let p = n * d;
    let (v0, v1, v2) = (b.w - a.w, c.w - a.w, p - a.w);
    let (d00, d01, d11) = (v0.dot(v0), v0.dot(v1), v1.dot(v1));
    let (d20, d21) = (v2.dot(v0), v2.dot(v1));
    let den = d00 * d11 - d01 * d01;
    let (u, v) = if den.abs() > 0.0 {
        ((d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den)
    } else {
        (0.0, 0.0)
    };
    let weights = [1.0 - u - v, u, v];
    let pa = a.a * weights[0] + b.a * weights[1] + c.a * weights[2];
    let pb = a.b * weights[0] + b.b * weights[1] + c.b * weights[2];
    Contact::Touching {
        point: (pa + pb) * 0.5,
        normal: n,
        depth: d.max(0.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn geometry() -> StarGeometry {
        StarGeometry::new(Star::new(1.0))
    }

    fn pose(t: DVec3) -> Pose {
        Pose {
            rotation: DMat3::IDENTITY,
            translation: t,
        }
    }

    #[test]
    fn cores_touch_at_twice_their_radius() {
        let g = geometry();
        // Along a diagonal the cores face each other; with the same orientation the spikes'
        // flanks face each other too and come nearer than the cores' 0.1.
        let dir = DVec3::new(1.0, 1.0, 1.0).normalize();
        assert!(g.intersects(&pose(dir * 0.59)));
        let c = g.contact(&pose(dir * 0.7));
        assert!(c.gap() > 0.0 && c.gap() < 0.1, "{c:?}");
        // The cores alone, with B's spikes turned away: B's core against A's core is the
        // nearest part pair only while no spike reaches in, which the contact must not miss.
        let c = balls(DVec3::ZERO, dir * 0.7, 0.3, 0.0);
        assert!((c.gap() - 0.1).abs() < 1e-12, "{c:?}");
    }

    #[test]
    fn spike_tips_meet_on_their_axis() {
        let g = geometry();
        // Tip against tip along x: apart by d - 2R.
        for (d, touching) in [(1.99, true), (2.0, true), (2.01, false)] {
            let p = pose(DVec3::new(d, 0.0, 0.0));
            assert_eq!(g.intersects(&p), touching, "d = {d}");
            assert_eq!(g.contact(&p).is_touching(), touching, "d = {d}");
        }
        let c = g.contact(&pose(DVec3::new(2.1, 0.0, 0.0)));
        assert!((c.gap() - 0.1).abs() < 1e-9, "{c:?}");
        assert!((c.normal() - DVec3::X).length() < 1e-9);
    }

    #[test]
    fn a_tip_against_the_core() {
        let g = geometry();
        // B rotated 45 degrees about z: its spikes along x and y miss A's +x spike's line,
        // and B's core meets A's +x tip when the centres are R + 0.3R apart... along x B's
        // own -x-ish spikes are off-axis, so the nearest part of B to A's tip is its core.
        let rot = DMat3::from_rotation_z(std::f64::consts::FRAC_PI_4)
            * DMat3::from_rotation_x(std::f64::consts::FRAC_PI_4);
        let p = |d: f64| Pose {
            rotation: rot,
            translation: DVec3::new(d, 0.0, 0.0),
        };
        let c = g.contact(&p(1.5));
        assert!(!c.is_touching());
        assert!(g.intersects(&p(1.25)));
    }

    #[test]
    fn coincident_centres_overlap_deeply() {
        let g = geometry();
        let c = g.contact(&pose(DVec3::ZERO));
        assert!(g.intersects(&pose(DVec3::ZERO)));
        match c {
            Contact::Touching { depth, normal, .. } => {
                assert!(depth >= 0.6 - 1e-9, "{depth}");
                assert!((normal.length() - 1.0).abs() < 1e-9);
            }
            Contact::Apart { .. } => panic!("coincident stars apart"),
        }
    }

    /// A cone's support point lies in the cone for every direction, the nearly axial ones
    /// included: there the perpendicular part is all rounding, and a rim point built from it
    /// once lay 0.03 R off the base disc, which let GJK report two spikes 0.0004 R apart when
    /// a separating plane kept them 0.018 R apart.
    #[test]
    fn support_points_stay_in_the_cone_along_the_axis() {
        let g = geometry();
        let axis = DVec3::new(-0.767198171862801, 0.3698868517216971, -0.5240140093678672);
        let cone = g.cone(DVec3::new(-0.95, -0.12, -0.21), axis.normalize());
        let off = perpendicular(cone.axis);
        for scale in [0.0, 1e-17, 1e-16, 1e-15, 1e-13, 1e-10, 1e-6, 1e-2] {
            for sign in [-1.0, 1.0] {
                let d = cone.axis * sign + off * scale;
                let p = cone.support(d) - cone.base;
                let s = p.dot(cone.axis);
                let radial = (p - cone.axis * s).length();
                assert!(
                    (-1e-12..=cone.height + 1e-12).contains(&s),
                    "axial {s} at scale {scale}, sign {sign}"
                );
                assert!(
                    radial <= cone.radius * (1.0 - s / cone.height) + 1e-12,
                    "radial {radial} at axial {s}, scale {scale}, sign {sign}"
                );
            }
        }
    }

    #[test]
    fn point_cone_matches_the_triangle() {
        let k = Cone {
            base: DVec3::ZERO,
            axis: DVec3::X,
            height: 1.0,
            radius: 0.25,
            slant: 1.0f64.hypot(0.25),
        };
        // Beyond the apex, on the axis.
        let (d, q, n) = point_cone(DVec3::new(1.5, 0.0, 0.0), &k);
        assert!((d - 0.5).abs() < 1e-12 && q == DVec3::X && n == DVec3::X);
        // Below the base, inside the rim.
        let (d, _, n) = point_cone(DVec3::new(-0.2, 0.1, 0.0), &k);
        assert!((d - 0.2).abs() < 1e-12 && n == DVec3::NEG_X);
        // Inside, nearest the slant side.
        let (d, _, _) = point_cone(DVec3::new(0.5, 0.0, 0.0), &k);
        let l = 1.0f64.hypot(0.25);
        assert!((d + 0.25 * 0.5 / l).abs() < 1e-12, "{d}");
    }

    #[test]
    fn cone_pairs_by_gjk_agree_with_a_closed_case() {
        // Two coaxial spikes tip to tip, and two crossing spikes whose axes pass at height e.
        let g = geometry();
        let ka = g.cone(DVec3::ZERO, DVec3::X);
        let kb = g.cone(DVec3::new(2.3, 0.0, 0.0), DVec3::NEG_X);
        let c = cones(&ka, &kb, g.eps);
        assert!((c.gap() - 0.3).abs() < 1e-9, "{c:?}");
        // Perpendicular spikes: A along x, B along y placed so B's axis crosses above A's apex
        // region; penetrating pairs come back with a unit normal and a depth.
        let kb = Cone {
            base: DVec3::new(0.5, -0.6, 0.1),
            axis: DVec3::Y,
            height: 1.0,
            radius: 0.25,
            slant: 1.0f64.hypot(0.25),
        };
        match cones(&ka, &kb, g.eps) {
            Contact::Touching { normal, depth, .. } => {
                assert!((normal.length() - 1.0).abs() < 1e-9);
                assert!(depth > 0.0 && depth < 0.25, "{depth}");
                // Moving B along the normal by the depth (plus a hair) separates them.
                let moved = Cone {
                    base: kb.base + normal * (depth + 1e-6),
                    ..kb
                };
                assert!(!cones(&ka, &moved, g.eps).is_touching());
                let less = Cone {
                    base: kb.base + normal * (depth - 1e-4),
                    ..kb
                };
                assert!(cones(&ka, &less, g.eps).is_touching());
            }
            c @ Contact::Apart { .. } => panic!("crossing spikes apart: {c:?}"),
        }
    }

    proptest::proptest! {
        /// The contact is the deepest of all 49 part pairs' (or, apart, the nearest): the
        /// search that orders only the part pairs that can touch and tests each yes or no
        /// first loses none, and the hull's plane test settles no touching pair.
        #[test]
        fn contact_is_the_extreme_part_pair(
            x in -2.1f64..2.1, y in -2.1f64..2.1, z in -2.1f64..2.1,
            q in proptest::array::uniform4(-1.0f64..1.0),
        ) {
            let g = geometry();
            let rotation = DMat3::from_quat(
                glam::DQuat::from_xyzw(q[0], q[1], q[2], q[3] + 1e-3).normalize(),
            );
            let pose = Pose { rotation, translation: DVec3::new(x, y, z) };
            let axes_b = b_axes(&pose);
            let all = (0..7)
                .flat_map(|i| (0..7).map(move |j| (i, j)))
                .map(|(i, j)| g.part_contact(pose.translation, &axes_b, i, j).signed_distance())
                .fold(f64::INFINITY, f64::min);
            let c = g.contact(&pose);
            proptest::prop_assert_eq!(c.is_touching(), g.intersects(&pose));
            if c.is_touching() {
                proptest::prop_assert!((c.signed_distance() - all).abs() <= 1e-6, "{c:?} vs {all}");
            } else {
                proptest::prop_assert!((c.signed_distance() - all).abs() <= 1e-9, "{c:?} vs {all}");
            }
        }

        /// For a touching pose, the contact without the touching test is the contact, bit for
        /// bit.
        #[test]
        fn a_touching_poses_contact_needs_no_second_test(
            x in -0.9f64..0.9, y in -0.9f64..0.9, z in -0.9f64..0.9,
            q in proptest::array::uniform4(-1.0f64..1.0),
        ) {
            let g = geometry();
            let rotation = DMat3::from_quat(
                glam::DQuat::from_xyzw(q[0], q[1], q[2], q[3] + 1e-3).normalize(),
            );
            let pose = Pose { rotation, translation: DVec3::new(x, y, z) };
            proptest::prop_assume!(g.intersects(&pose));
            proptest::prop_assert_eq!(g.contact_of_touching(&pose), g.contact(&pose));
        }

        /// Two spikes' gap along any direction never exceeds their distance (it is a proof of
        /// separation, never a guess), and along the direction between the nearest points it
        /// is their distance, to within what GJK proved: where its search stalls on a cone's
        /// curved rim (a few cases in a thousand) the distance it reports is an upper bound a
        /// few 1e-6 R above the lower bound it proved, and the gap lies between the two.
        #[test]
        fn the_axis_gap_bounds_the_spikes_distance(
            x in -1.2f64..1.2, y in -1.2f64..1.2, z in -1.2f64..1.2,
            q in proptest::array::uniform4(-1.0f64..1.0),
            u in proptest::array::uniform3(-1.0f64..1.0),
            i in 0usize..6, j in 0usize..6,
        ) {
            let g = geometry();
            let rotation = DMat3::from_quat(
                glam::DQuat::from_xyzw(q[0], q[1], q[2], q[3] + 1e-3).normalize(),
            );
            let pose = Pose { rotation, translation: DVec3::new(x, y, z) };
            let (t, axis_b) = (pose.translation, b_axes(&pose)[j]);
            let (ka, kb) = (g.cone(DVec3::ZERO, AXES[i]), g.cone(t, axis_b));
            let search = gjk(&ka, &kb, g.eps, false);
            let c = cones_from(&ka, &kb, &search, g.eps);
            let u = DVec3::from_array(u).normalize_or(DVec3::X);
            let gap = g.axis_gap(AXES[i], t, axis_b, u);
            proptest::prop_assert!(gap <= c.signed_distance().max(0.0) + 1e-9, "{gap} > {c:?}");
            if let Contact::Apart { distance, point_a, point_b } = c {
                let along = g.axis_gap(AXES[i], t, axis_b, (point_b - point_a) / distance);
                proptest::prop_assert!(
                    along <= distance + 1e-6 && along >= search.lower.min(distance) - 1e-6,
                    "{along} outside [{}, {distance}]",
                    search.lower
                );
            }
        }
    }
}
