//! An independent judge of the star contact: whether two stars touch, and a bracket on their
//! distance, by branch and bound over patches of their surfaces.
//!
//! It shares no code with the engine's closed forms and GJK (`foveal_engine::star_contact`), not
//! even the vector type: the judge has its own [`V3`], and is given the two stars' relative pose
//! as plain numbers. `foveal-bench shape-check` holds whole scenes to it; the engine's
//! integration test `shape_oracle` includes this file by path and holds random and targeted
//! poses to it.
//!
//! # The star
//! Bounding radius R; a core ball of radius 0.3R at the centre; six solid cones along ±x, ±y, ±z
//! of the body frame, each with its base disc of radius 0.25R centred at the body centre and its
//! apex at distance R (docs/DESIGN.md "Shape"). Closed solids.
//!
//! # Distance from a point to a star
//! The least over the seven parts, 0 inside any. To the core ball, the centre distance less the
//! radius. To a cone, inside it iff `0 <= t <= R` and `rho <= 0.25R (1 - t/R)` (height `t` along
//! the axis, `rho` from it); outside it, its nearest point is on its surface, the base disc or a
//! generator segment (apex to rim). The disc's nearest point is the point's projection on the base
//! plane pulled in to the rim. Among generators, the one through the rim point in the direction of
//! the point's radial component `r` is nearest: a point of the generator through rim direction `e`
//! at fraction `s` from the apex is `P + s (b e - P)` (`P` the apex), whose squared distance to
//! the point depends on `e` only through `-2 s b (r . e)`, least for `e` along `r` at every `s`.
//! So the distance is the least of a 3D point-to-disc and a 3D point-to-segment distance.
//!
//! # Surfaces, patches and bounds
//! Every point of the surface of a star S lies on the surface of one of its parts. Each part's
//! surface is parametrised over a rectangle: the core by polar angle and azimuth, a cone's lateral
//! surface by the fraction of the way from rim to apex and azimuth, its base by the fraction of the
//! radius and azimuth. A *patch* is a sub-rectangle, evaluated at its centre `c` against the other
//! star T:
//! - **upper bound**: `c` is a point of S, so dist(S, T) <= d(c, T); d(c, T) = 0 (c in T) proves
//!   that the stars touch.
//! - **lower bound** on dist(x, T) over the patch, the least over T's parts K of the larger of:
//!   - *Lipschitz*: d(c, K) - rho, where rho bounds |x - c| over the patch: a path from `c` along
//!     the two coordinate lines (first the azimuth at `c`'s other coordinate, then the other
//!     coordinate), whose length is at most `(radius of the azimuth circle at c) * (half the
//!     azimuth width) + (speed along the other coordinate) * (half its width)`. This is the
//!     plain sampling bound: with every surface point within rho of a sample, the sampled
//!     minimum d_s satisfies d_s - rho <= dist <= d_s;
//!   - *separating axis*: for any unit g, dist(x, K) >= g.x - h_K(g), h_K the support function
//!     (`0.3R` for the ball; `max(R g.a, 0.25R |g - (g.a) a|)` for the cone along `a`), and the
//!     least of g.x over the patch is exact: on every surface g.x is, for each value of the
//!     non-azimuth coordinate, a non-negative multiple of `(g.e1) cos(phi) + (g.e2) sin(phi)`
//!     plus a term without phi, least at an end of the azimuth range or where `(cos, sin)` points
//!     against `(g.e1, g.e2)`; what remains is linear in the height or radius fraction (least at
//!     an end) or, on the ball, the same cos-sin form in the polar angle. With g the direction
//!     from K's nearest point to `c` this bound is second-order accurate where a patch is tangent
//!     to a level set of the distance, so refinement converges in a few dozen splits.
//!
//!   A part K whose bounding sphere is farther from `c` than rho plus the least bound so far is
//!   not evaluated: it cannot lower the least.
//!
//!   The least lower bound of all patches not yet split (and of those pruned) bounds
//!   dist(surface of S, T), which is dist(S, T) when the stars are apart: the point of S nearest
//!   T is on S's surface. Every lower bound is lowered by [`ROUNDING`] R for the f64 arithmetic
//!   (coordinates of the order of R, errors of the order of 1e-15 R).
//! - **search**: split the patch with the least lower bound in two along the coordinate whose
//!   variation costs the bound most, until a sample falls in T (touching), the bracket [least
//!   lower bound, least sampled distance] is narrower than [`Oracle::precision`], or the
//!   evaluation cap is reached. Parts of S whose bounding sphere cannot beat the best sample are
//!   never opened.
//!
//! Both directions are searched (B's surface against A, then A's against B), each a complete
//! bracket; they are combined (the larger lower, the smaller upper bound) and must agree, or the
//! judge panics: a disagreement is a bug of the judge. [`Oracle::judge`] brackets the distance
//! to the precision (1e-10 R by default) searching B's surface, and searches A's only until the
//! verdict is settled; [`Oracle::verdict`] stops both searches as soon as the verdict is
//! settled, which is what checking a whole scene's touching answers needs.
//!
//! # Verdict
//! - [`Verdict::Touching`]: a sample of one star lies in the other (the sampled distance is 0).
//! - [`Verdict::Apart`]: the lower bound exceeds [`TOLERANCE`] R, the engine's touching tolerance,
//!   plus rounding: the engine must call the pair apart.
//! - [`Verdict::Ambiguous`]: neither (a contact within the bracket's width of grazing).

use std::cmp::Ordering;
use std::collections::BinaryHeap;
use std::ops::{Add, Mul, Neg, Sub};

/// Core ball radius as a fraction of R.
pub const CORE_FRACTION: f64 = 0.3;
/// Spike base disc radius as a fraction of R.
pub const BASE_FRACTION: f64 = 0.25;
/// Distances at or below this fraction of R count as touching (the engine's tolerance).
pub const TOLERANCE: f64 = 1e-9;
/// Allowance for f64 rounding, as a fraction of R: every lower bound is lowered by it, and a
/// pair is surely apart only beyond [`TOLERANCE`] plus it.
pub const ROUNDING: f64 = 1e-12;

/// A 3D vector of the judge's own.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct V3 {
    /// x.
    pub x: f64,
    /// y.
    pub y: f64,
    /// z.
    pub z: f64,
}

impl V3 {
    /// The vector (x, y, z).
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Self { x, y, z }
    }

    /// The zero vector.
    pub const ZERO: Self = Self::new(0.0, 0.0, 0.0);

    /// From an array.
    pub const fn from_array(a: [f64; 3]) -> Self {
        Self::new(a[0], a[1], a[2])
    }

    /// As an array.
    pub const fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }

    /// Dot product.
    #[inline]
    pub fn dot(self, o: Self) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Cross product.
    #[inline]
    pub fn cross(self, o: Self) -> Self {
        Self::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// Euclidean length.
    #[inline]
    pub fn norm(self) -> f64 {
        self.dot(self).sqrt()
    }

    /// Component `k` (0 x, 1 y, 2 z).
    #[inline]
    fn get(self, k: usize) -> f64 {
        match k {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }
}

impl Add for V3 {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl Sub for V3 {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Neg for V3 {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl Mul<f64> for V3 {
    type Output = Self;
    #[inline]
    fn mul(self, s: f64) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

/// Unit vector along body axis `k` (0 x, 1 y, 2 z).
const fn unit(k: usize) -> V3 {
    match k {
        0 => V3::new(1.0, 0.0, 0.0),
        1 => V3::new(0.0, 1.0, 0.0),
        _ => V3::new(0.0, 0.0, 1.0),
    }
}

/// Spike `c` (0..6): its body axis (0 x, 1 y, 2 z) and direction along it (+1 for even `c`,
/// -1 for odd).
fn spike(c: usize) -> (usize, f64) {
    (c / 2, if c.is_multiple_of(2) { 1.0 } else { -1.0 })
}

/// A star placed in the judging frame: its centre and its body axes (x, y, z).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Centre.
    pub centre: V3,
    /// The body's x, y and z axes (the columns of its rotation).
    pub axes: [V3; 3],
}

impl Placement {
    /// At the origin, unrotated.
    pub const IDENTITY: Self = Self {
        centre: V3::ZERO,
        axes: [unit(0), unit(1), unit(2)],
    };

    /// The frame of the judging star seen from this one: the inverse placement (the rotation's
    /// transpose; the axes are taken to be orthonormal).
    pub fn inverse(&self) -> Self {
        let [a, b, c] = self.axes;
        // The columns of the transpose are the rows of the rotation.
        let axes = [
            V3::new(a.x, b.x, c.x),
            V3::new(a.y, b.y, c.y),
            V3::new(a.z, b.z, c.z),
        ];
        let t = self.centre;
        let centre = -V3::new(a.dot(t), b.dot(t), c.dot(t));
        Self { centre, axes }
    }

    /// A point given in this star's body frame, in the judging frame.
    pub fn judging_point(&self, p: V3) -> V3 {
        self.centre + self.axes[0] * p.x + self.axes[1] * p.y + self.axes[2] * p.z
    }

    /// A point of the judging frame, in this star's body frame.
    pub fn body_point(&self, p: V3) -> V3 {
        let d = p - self.centre;
        V3::new(
            self.axes[0].dot(d),
            self.axes[1].dot(d),
            self.axes[2].dot(d),
        )
    }
}

/// What the judge says about a pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// A sample of one star lies in the other.
    Touching,
    /// Farther apart than the touching tolerance, proven.
    Apart,
    /// Within the bracket's width of grazing: neither proven.
    Ambiguous,
}

/// The judge's answer on a pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Judgement {
    /// The verdict.
    pub verdict: Verdict,
    /// A lower bound on the distance between the stars (meaningful when not touching).
    pub lower: f64,
    /// An upper bound on it: the least sampled distance (0 when touching).
    pub upper: f64,
    /// Patches evaluated, both directions.
    pub evaluations: usize,
}

/// What one direction's search found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    /// Lower bound on dist(surface of S, T).
    pub lower: f64,
    /// Least sampled distance (0 if a sample is in T).
    pub upper: f64,
    /// The sample that gave `upper`, in the judging frame.
    pub witness: V3,
    /// Patches evaluated.
    pub evaluations: usize,
}

impl Bracket {
    /// Whether a sample fell in T.
    pub fn touching(&self) -> bool {
        self.upper <= 0.0
    }
}

/// The judge, for stars of one bounding radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oracle {
    /// Bounding radius R (cone height).
    radius: f64,
    /// Core ball radius.
    core: f64,
    /// Spike base disc radius.
    base: f64,
    /// Bounding spheres of the parts of the star at the origin: the core ball; each cone's
    /// smallest, through its apex and rim.
    spheres: [(V3, f64); 7],
    /// A search stops when its bracket is this narrow (scene units).
    pub precision: f64,
    /// A search stops after this many patch evaluations.
    pub cap: usize,
}

/// Which part's surface a patch lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// The core ball: (polar angle from the body z axis, azimuth).
    Core,
    /// A cone's lateral surface: (fraction from rim to apex, azimuth).
    Lateral,
    /// A cone's base disc: (fraction of the radius, azimuth).
    Base,
}

/// A part surface of S in the judging frame: `o` the part's centre (the star's), `a` the
/// cone's axis (the body z axis for the core), `e1`, `e2` completing an orthonormal frame in
/// which the azimuth is measured.
#[derive(Debug, Clone, Copy)]
struct Surface {
    kind: Kind,
    o: V3,
    a: V3,
    e1: V3,
    e2: V3,
}

/// A sub-rectangle of a surface's parameters, with the (cos, sin) of its angles' ends (of the
/// polar angle on the core, of the azimuth everywhere). Neighbours share the values at their
/// common edge, so the rectangles of a split tile their parent exactly.
#[derive(Debug, Clone, Copy)]
struct Rect {
    lo: [f64; 2],
    hi: [f64; 2],
    trig_lo: [(f64, f64); 2],
    trig_hi: [(f64, f64); 2],
}

impl Rect {
    /// The rectangle `lo`..`hi`.
    fn new(lo: [f64; 2], hi: [f64; 2]) -> Self {
        let cs = |t: f64| (t.cos(), t.sin());
        Self {
            lo,
            hi,
            trig_lo: [cs(lo[0]), cs(lo[1])],
            trig_hi: [cs(hi[0]), cs(hi[1])],
        }
    }

    /// (cos, sin) midway between the ends of coordinate `k`'s angle: the bisector of an arc
    /// below pi.
    fn trig_mid(&self, k: usize) -> (f64, f64) {
        let (x, y) = (
            self.trig_lo[k].0 + self.trig_hi[k].0,
            self.trig_lo[k].1 + self.trig_hi[k].1,
        );
        let n = (x * x + y * y).sqrt();
        (x / n, y / n)
    }

    /// The two halves along coordinate `k`.
    fn halves(&self, k: usize) -> [Self; 2] {
        let cut = (self.lo[k] + self.hi[k]) * 0.5;
        let trig = self.trig_mid(k);
        let (mut a, mut b) = (*self, *self);
        a.hi[k] = cut;
        a.trig_hi[k] = trig;
        b.lo[k] = cut;
        b.trig_lo[k] = trig;
        [a, b]
    }
}

/// [`Patch::split`] of a whole surface not yet cut into its first patches.
const OPEN: u8 = u8::MAX;

/// A patch: a rectangle of a surface's parameters, with its lower bound.
#[derive(Debug, Clone, Copy)]
struct Patch {
    surface: u8,
    rect: Rect,
    lower: f64,
    /// The coordinate to split it along.
    split: u8,
    /// Its largest extent in space (scene units).
    size: f64,
}

/// Heap entry: a patch index, ordered by least lower bound first.
#[derive(Debug, Clone, Copy)]
struct Entry {
    lower: f64,
    index: usize,
}

impl PartialEq for Entry {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Entry {
    fn cmp(&self, o: &Self) -> Ordering {
        // Reversed: BinaryHeap is a max-heap.
        o.lower
            .total_cmp(&self.lower)
            .then(o.index.cmp(&self.index))
    }
}

/// The least of `kx cos(t) + ky sin(t)` over `t` in an arc of width below pi from angle `a`
/// (cos, sin = `ca`, `sa`) to angle `b` (`cb`, `sb`).
#[inline]
fn arc_min(kx: f64, ky: f64, (ca, sa): (f64, f64), (cb, sb): (f64, f64)) -> f64 {
    let ends = (kx * ca + ky * sa).min(kx * cb + ky * sb);
    // The unconstrained least is where (cos, sin) points along -(kx, ky); it lies in the arc iff
    // it is anticlockwise of the start and clockwise of the end (the arc is shorter than pi).
    let (wx, wy) = (-kx, -ky);
    if ca * wy - sa * wx >= 0.0 && wx * sb - wy * cb >= 0.0 {
        ends.min(-(kx * kx + ky * ky).sqrt())
    } else {
        ends
    }
}

impl Oracle {
    /// The judge for stars of bounding radius `radius`, with a precision of 1e-10 R and a cap of
    /// 200,000 evaluations per direction.
    pub fn new(radius: f64) -> Self {
        let (core, base) = (CORE_FRACTION * radius, BASE_FRACTION * radius);
        // The sphere through a cone's apex and rim, centred on its axis at `off`.
        let off = (radius * radius - base * base) / (2.0 * radius);
        let spheres = std::array::from_fn(|j| {
            if j == 0 {
                (V3::ZERO, core)
            } else {
                let (k, sign) = spike(j - 1);
                (unit(k) * (sign * off), radius - off)
            }
        });
        Self {
            radius,
            core,
            base,
            spheres,
            precision: 1e-10 * radius,
            cap: 200_000,
        }
    }

    /// Bounding radius R.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Core ball radius.
    pub fn core(&self) -> f64 {
        self.core
    }

    /// Spike base disc radius.
    pub fn base(&self) -> f64 {
        self.base
    }

    /// Whether the star at the origin (unrotated) contains `p`.
    pub fn contains(&self, p: V3) -> bool {
        self.distance(p) <= 0.0
    }

    /// Distance from `p` to the star at the origin, unrotated (0 inside).
    pub fn distance(&self, p: V3) -> f64 {
        (0..7)
            .map(|j| self.part_distance(j, p).0)
            .fold(f64::INFINITY, f64::min)
    }

    /// Distance from `p` to part `j` of the star at the origin (0 the core, `1 + 2k + s` the cone
    /// along +axis `k` for `s = 0`, -axis `k` for `s = 1`), and the part's point nearest `p`
    /// (`p` itself inside, where the distance is 0 or, in the core, negative).
    pub fn part_distance(&self, j: usize, p: V3) -> (f64, V3) {
        if j == 0 {
            let n = p.norm();
            let d = n - self.core;
            return if d <= 0.0 {
                (d, p)
            } else {
                (d, p * (self.core / n))
            };
        }
        let (k, sign) = spike(j - 1);
        let a = unit(k) * sign;
        let (h, b) = (self.radius, self.base);
        let t = p.dot(a);
        let radial = p - a * t;
        let rho = radial.norm();
        if t >= 0.0 && t <= h && rho <= b * (1.0 - t / h) {
            return (0.0, p);
        }
        // Base disc: the projection on the base plane, pulled in to the rim.
        let on_disc = if rho > b { radial * (b / rho) } else { radial };
        let d_disc = (p - on_disc).norm();
        // The generator in p's meridian half-plane, from the apex to the rim.
        let rim = if rho > 0.0 {
            radial * (b / rho)
        } else {
            unit((k + 1) % 3) * b
        };
        let apex = a * h;
        let v = rim - apex;
        let s = ((p - apex).dot(v) / v.dot(v)).clamp(0.0, 1.0);
        let on_slant = apex + v * s;
        let d_slant = (p - on_slant).norm();
        if d_disc <= d_slant {
            (d_disc, on_disc)
        } else {
            (d_slant, on_slant)
        }
    }

    /// The bounding sphere of part `j` of the star at the origin: the core ball; a cone's
    /// smallest, through its apex and rim.
    #[inline]
    fn bound(&self, j: usize) -> (V3, f64) {
        self.spheres[j]
    }

    /// Support function of part `j` of the star at the origin: the largest `g . y` over its points.
    fn support(&self, j: usize, g: V3) -> f64 {
        if j == 0 {
            return self.core * g.norm();
        }
        let (k, sign) = spike(j - 1);
        let ga = sign * g.get(k);
        let (u, v) = (g.get((k + 1) % 3), g.get((k + 2) % 3));
        let perp = (u * u + v * v).sqrt();
        (self.radius * ga).max(self.base * perp)
    }

    /// The 13 part surfaces of a star placed at `s`: 0 the core, `1 + 2c` the lateral surface
    /// and `2 + 2c` the base of cone `c` (cone `c` along +axis `c / 2` for even `c`, else -axis).
    fn surfaces(&self, s: &Placement) -> [Surface; 13] {
        let core = Surface {
            kind: Kind::Core,
            o: s.centre,
            a: s.axes[2],
            e1: s.axes[0],
            e2: s.axes[1],
        };
        let mut out = [core; 13];
        for c in 0..6 {
            let (k, sign) = spike(c);
            let a = s.axes[k] * sign;
            let (e1, e2) = (s.axes[(k + 1) % 3], s.axes[(k + 2) % 3]);
            out[1 + 2 * c] = Surface {
                kind: Kind::Lateral,
                o: s.centre,
                a,
                e1,
                e2,
            };
            out[2 + 2 * c] = Surface {
                kind: Kind::Base,
                ..out[1 + 2 * c]
            };
        }
        out
    }

    /// The point of a surface at parameters `(p, phi)` given as `p` and `(cos, sin)` of the
    /// angles.
    fn point(&self, sf: &Surface, p: f64, (cp, sp): (f64, f64), (cf, sf_): (f64, f64)) -> V3 {
        let e = sf.e1 * cf + sf.e2 * sf_;
        match sf.kind {
            Kind::Core => sf.o + (e * sp + sf.a * cp) * self.core,
            Kind::Lateral => sf.o + sf.a * (p * self.radius) + e * ((1.0 - p) * self.base),
            Kind::Base => sf.o + e * (p * self.base),
        }
    }

    /// Evaluate a patch of surface `sf` against the star at the origin: its centre's distance
    /// (0 if inside) and the centre, the patch's lower bound, the coordinate to split along and
    /// its size.
    fn evaluate(&self, sf: &Surface, r: &Rect) -> (f64, V3, f64, u8, f64) {
        let (lo, hi) = (r.lo, r.hi);
        let mid = [(lo[0] + hi[0]) * 0.5, (lo[1] + hi[1]) * 0.5];
        let half = [(hi[0] - lo[0]) * 0.5, (hi[1] - lo[1]) * 0.5];
        let (phi_lo, phi_hi, phi_mid) = (r.trig_lo[1], r.trig_hi[1], r.trig_mid(1));
        let (p_lo, p_hi, p_mid) = match sf.kind {
            Kind::Core => (r.trig_lo[0], r.trig_hi[0], r.trig_mid(0)),
            _ => ((0.0, 0.0), (0.0, 0.0), (0.0, 0.0)),
        };
        let c = self.point(sf, mid[0], p_mid, phi_mid);
        // Extents along each coordinate from the centre (path lengths), their sum bounds
        // |x - c| over the patch.
        let slant = (self.radius * self.radius + self.base * self.base).sqrt();
        let ext = match sf.kind {
            Kind::Core => [self.core * half[0], self.core * p_mid.1 * half[1]],
            Kind::Lateral => [slant * half[0], (1.0 - mid[0]) * self.base * half[1]],
            Kind::Base => [self.base * half[0], mid[0] * self.base * half[1]],
        };
        let reach = ext[0] + ext[1];
        let size = 2.0 * ext[0].max(ext[1]);
        let rounding = ROUNDING * self.radius;
        let mut upper = f64::INFINITY;
        let mut lower = f64::INFINITY;
        // T's parts by their bounding spheres: a part whose sphere is farther than the least
        // bound so far cannot lower it. The nearest first, then the others in order.
        let crude: [f64; 7] = std::array::from_fn(|j| {
            let (cj, rj) = self.bound(j);
            (c - cj).norm() - rj - reach
        });
        let first = (1..7).fold(0, |f, j| if crude[j] < crude[f] { j } else { f });
        // The least of g.x over the patch given the least over its azimuth range `m` of
        // `(g.e1) cos + (g.e2) sin`, and `ga = g.a`.
        let least = |ga: f64, m: f64| -> f64 {
            match sf.kind {
                Kind::Core => self.core * arc_min(ga, m, p_lo, p_hi),
                Kind::Lateral => {
                    let at = |u: f64| u * self.radius * ga + (1.0 - u) * self.base * m;
                    at(lo[0]).min(at(hi[0]))
                }
                Kind::Base => (lo[0] * self.base * m).min(hi[0] * self.base * m),
            }
        };
        // The direction of the part giving the least bound, if its separating axis gave it.
        let mut axis: Option<V3> = None;
        for j in std::iter::once(first).chain((0..7).filter(|&j| j != first)) {
            if crude[j] >= lower {
                continue;
            }
            let (d, q) = self.part_distance(j, c);
            if d <= 0.0 {
                return (0.0, c, f64::NEG_INFINITY, 0, size);
            }
            upper = upper.min(d);
            let g = c - q;
            let g = g * (1.0 / g.norm());
            let (g1, g2) = (g.dot(sf.e1), g.dot(sf.e2));
            let plane = g.dot(sf.o) + least(g.dot(sf.a), arc_min(g1, g2, phi_lo, phi_hi))
                - self.support(j, g);
            let lipschitz = d - reach;
            let bound = plane.max(lipschitz) - rounding;
            if bound < lower {
                lower = bound;
                axis = (plane >= lipschitz).then_some(g);
            }
        }
        let split = match axis {
            // What each coordinate's variation alone costs the separating-axis bound: the
            // least of g.x along the coordinate line through the centre, against g.c.
            Some(g) => {
                let (ga, g1, g2) = (g.dot(sf.a), g.dot(sf.e1), g.dot(sf.e2));
                let m = arc_min(g1, g2, phi_lo, phi_hi);
                let at_mid = g1 * phi_mid.0 + g2 * phi_mid.1;
                let (along0, along1) = match sf.kind {
                    Kind::Core => (
                        self.core * arc_min(ga, at_mid, p_lo, p_hi),
                        self.core * (ga * p_mid.0 + m * p_mid.1),
                    ),
                    Kind::Lateral => (
                        least(ga, at_mid),
                        mid[0] * self.radius * ga + (1.0 - mid[0]) * self.base * m,
                    ),
                    Kind::Base => (least(ga, at_mid), mid[0] * self.base * m),
                };
                if along0 <= along1 { 0 } else { 1 }
            }
            None => {
                if ext[0] >= ext[1] {
                    0
                } else {
                    1
                }
            }
        };
        (upper, c, lower, split, size)
    }

    /// Initial patches of each kind of surface: (parameter-0 cuts, azimuth cuts). Azimuth arcs
    /// and polar arcs stay below pi, as [`arc_min`] needs.
    fn initial(kind: Kind) -> (usize, usize, f64) {
        match kind {
            Kind::Core => (2, 4, std::f64::consts::PI),
            Kind::Lateral => (2, 4, 1.0),
            Kind::Base => (1, 4, 1.0),
        }
    }

    /// Search the surface of star S (placed at `s`) against the star at the origin, to
    /// [`Self::precision`]; with `settle`, only until the verdict is settled (a sample inside,
    /// or the lower bound beyond the tolerance).
    pub fn bracket(&self, s: &Placement, settle: bool) -> Bracket {
        let surfaces = self.surfaces(s);
        let rounding = ROUNDING * self.radius;
        let apart = (TOLERANCE + ROUNDING) * self.radius;
        let mut patches: Vec<Patch> = Vec::new();
        let mut heap = BinaryHeap::new();
        // Each surface of S enters whole, unopened, with a lower bound from bounding spheres:
        // the core's ball, a lateral surface in its cone's sphere, a base disc in its own.
        let whole = Rect::new([0.0; 2], [0.0; 2]);
        for (id, sf) in surfaces.iter().enumerate() {
            let (centre, radius) = match sf.kind {
                Kind::Core => (sf.o, self.core),
                Kind::Lateral => {
                    let (c, r) = self.bound(1);
                    (sf.o + sf.a * c.x, r)
                }
                Kind::Base => (sf.o, self.base),
            };
            let lower = (0..7)
                .map(|j| {
                    let (cj, rj) = self.bound(j);
                    (centre - cj).norm() - radius - rj
                })
                .fold(f64::INFINITY, f64::min)
                - rounding;
            heap.push(Entry {
                lower,
                index: patches.len(),
            });
            patches.push(Patch {
                surface: id as u8,
                rect: whole,
                lower,
                split: OPEN,
                size: f64::INFINITY,
            });
        }
        let mut upper = f64::INFINITY;
        let mut witness = s.centre;
        let mut pruned = f64::INFINITY;
        let mut evaluations = 0usize;
        let done = |lower: f64, upper: f64, witness: V3, evaluations: usize| Bracket {
            lower: lower.min(upper),
            upper,
            witness,
            evaluations,
        };
        let tau = std::f64::consts::TAU;
        let mut children: Vec<Rect> = Vec::with_capacity(8);
        loop {
            let Some(top) = heap.pop() else {
                return done(pruned, upper, witness, evaluations);
            };
            let p = patches[top.index];
            if p.lower >= upper - self.precision
                || (settle && p.lower > apart)
                || evaluations >= self.cap
                || p.size < rounding
            {
                return done(p.lower.min(pruned), upper, witness, evaluations);
            }
            let sf = &surfaces[usize::from(p.surface)];
            children.clear();
            if p.split == OPEN {
                let (n0, n1, span0) = Self::initial(sf.kind);
                for i0 in 0..n0 {
                    for i1 in 0..n1 {
                        let (f0, f1) = (i0 as f64 / n0 as f64, i1 as f64 / n1 as f64);
                        let (t0, t1) = ((i0 + 1) as f64 / n0 as f64, (i1 + 1) as f64 / n1 as f64);
                        children.push(Rect::new([span0 * f0, tau * f1], [span0 * t0, tau * t1]));
                    }
                }
            } else {
                children.extend(p.rect.halves(usize::from(p.split)));
            }
            for &rect in &children {
                let (d, c, lower, split, size) = self.evaluate(sf, &rect);
                evaluations += 1;
                if d < upper {
                    upper = d;
                    witness = c;
                }
                if upper <= 0.0 {
                    return done(f64::NEG_INFINITY, 0.0, witness, evaluations);
                }
                if lower >= upper - self.precision {
                    pruned = pruned.min(lower);
                    continue;
                }
                heap.push(Entry {
                    lower,
                    index: patches.len(),
                });
                patches.push(Patch {
                    surface: p.surface,
                    rect,
                    lower,
                    split,
                    size,
                });
            }
        }
    }

    /// Judge star B placed at `b` (its centre and axes in A's frame) against star A at the
    /// origin, bracketing the distance to [`Self::precision`] (B's surface searched to it, A's
    /// until the verdict is settled).
    ///
    /// # Panics
    /// If the two directions' brackets contradict each other: a bug of the judge.
    pub fn judge(&self, b: &Placement) -> Judgement {
        self.judge_to(b, false)
    }

    /// [`Self::judge`], searching only until the verdict is settled: the bracket of a pair
    /// proven apart is then wide.
    pub fn verdict(&self, b: &Placement) -> Judgement {
        self.judge_to(b, true)
    }

    fn judge_to(&self, b: &Placement, settle: bool) -> Judgement {
        let first = self.bracket(b, settle);
        if first.touching() {
            return Judgement {
                verdict: Verdict::Touching,
                lower: first.lower,
                upper: 0.0,
                evaluations: first.evaluations,
            };
        }
        // The reverse search needs only settle the verdict: the first bracket is complete.
        let second = self.bracket(&b.inverse(), true);
        let slack = 1e-9 * self.radius;
        assert!(
            second.lower <= first.upper + slack && first.lower <= second.upper + slack,
            "the judge's two directions disagree on {b:?}: {first:?} against {second:?}"
        );
        let evaluations = first.evaluations + second.evaluations;
        if second.touching() {
            return Judgement {
                verdict: Verdict::Touching,
                lower: second.lower,
                upper: 0.0,
                evaluations,
            };
        }
        let lower = first.lower.max(second.lower);
        let upper = first.upper.min(second.upper);
        let verdict = if lower > (TOLERANCE + ROUNDING) * self.radius {
            Verdict::Apart
        } else {
            Verdict::Ambiguous
        };
        Judgement {
            verdict,
            lower,
            upper,
            evaluations,
        }
    }

    /// Distance from a point given in A's frame to star B placed at `b` (0 inside).
    pub fn distance_to(&self, b: &Placement, p: V3) -> f64 {
        self.distance(b.body_point(p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (splitmix64), so these tests need no dependency.
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^= z >> 31;
            (z >> 11) as f64 / (1u64 << 53) as f64
        }

        fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.next()
        }

        fn point(&mut self, r: f64) -> V3 {
            V3::new(self.range(-r, r), self.range(-r, r), self.range(-r, r))
        }
    }

    #[test]
    fn cone_distance_is_the_least_over_generators_and_the_disc() {
        // Against a scan of every generator segment by azimuth (golden-section refined) and of
        // the base disc on a fine polar grid: the closed distance is never above the scan's and
        // the scan comes within its resolution.
        let o = Oracle::new(1.0);
        let mut rng = Rng(7);
        for _ in 0..150 {
            let p = rng.point(1.6);
            for j in 1..7 {
                let (d, q) = o.part_distance(j, p);
                let (k, sign) = spike(j - 1);
                let a = unit(k) * sign;
                let (e1, e2) = (unit((k + 1) % 3), unit((k + 2) % 3));
                let apex = a * o.radius;
                let seg = |phi: f64| -> f64 {
                    let rim = (e1 * phi.cos() + e2 * phi.sin()) * o.base;
                    let v = rim - apex;
                    let s = ((p - apex).dot(v) / v.dot(v)).clamp(0.0, 1.0);
                    (p - (apex + v * s)).norm()
                };
                let n = 720;
                let mut best = f64::INFINITY;
                let mut at = 0.0;
                for i in 0..n {
                    let phi = std::f64::consts::TAU * i as f64 / n as f64;
                    let v = seg(phi);
                    if v < best {
                        best = v;
                        at = phi;
                    }
                }
                let (mut lo, mut hi) = (at - 0.01, at + 0.01);
                for _ in 0..80 {
                    let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
                    if seg(m1) < seg(m2) {
                        hi = m2;
                    } else {
                        lo = m1;
                    }
                }
                best = best.min(seg((lo + hi) * 0.5));
                // The disc on a polar grid of spacing at most 0.0044 (radius 0.25).
                for i in 0..=100 {
                    for jj in 0..180 {
                        let s = o.base * i as f64 / 100.0;
                        let phi = std::f64::consts::TAU * jj as f64 / 180.0;
                        let x = (e1 * phi.cos() + e2 * phi.sin()) * s;
                        best = best.min((p - x).norm());
                    }
                }
                let inside = {
                    let t = p.dot(a);
                    let rho = (p - a * t).norm();
                    (0.0..=o.radius).contains(&t) && rho <= o.base * (1.0 - t / o.radius)
                };
                if inside {
                    assert_eq!(d, 0.0);
                    continue;
                }
                assert!(d <= best + 1e-12, "{p:?} cone {j}: {d} > scan {best}");
                assert!(d >= best - 5e-3, "{p:?} cone {j}: {d} < scan {best}");
                // The distance is attained: its point is on the cone.
                assert!(((p - q).norm() - d).abs() < 1e-12);
                assert!(o.part_distance(j, q).0 <= 1e-12, "{q:?} off cone {j}");
            }
        }
    }

    #[test]
    fn support_is_the_largest_projection() {
        let o = Oracle::new(1.0);
        let mut rng = Rng(11);
        for _ in 0..200 {
            let g = rng.point(1.0);
            let g = g * (1.0 / g.norm());
            for j in 1..7 {
                let (k, sign) = spike(j - 1);
                let a = unit(k) * sign;
                let (e1, e2) = (unit((k + 1) % 3), unit((k + 2) % 3));
                let mut best = g.dot(a * o.radius);
                for i in 0..3600 {
                    let phi = std::f64::consts::TAU * i as f64 / 3600.0;
                    best = best.max(g.dot((e1 * phi.cos() + e2 * phi.sin()) * o.base));
                }
                let h = o.support(j, g);
                assert!(h >= best - 1e-12 && h <= best + 1e-6, "{h} against {best}");
            }
        }
    }

    #[test]
    fn patch_bounds_hold_on_dense_samples() {
        // Every lower bound a patch reports is at most the distance of every point of the patch.
        let o = Oracle::new(1.0);
        let mut rng = Rng(3);
        for _ in 0..60 {
            let s = Placement {
                centre: rng.point(1.5),
                axes: random_axes(&mut rng),
            };
            for (id, sf) in o.surfaces(&s).iter().enumerate() {
                let (_, _, span0) = Oracle::initial(sf.kind);
                let a0 = rng.range(0.0, span0 * 0.7);
                let a1 = rng.range(0.0, 5.0);
                let lo = [a0, a1];
                let hi = [a0 + rng.range(0.0, span0 * 0.3), a1 + rng.range(0.0, 1.5)];
                let (d, c, lower, _, _) = o.evaluate(sf, &Rect::new(lo, hi));
                assert!(
                    (o.distance(c) - d).abs() < 1e-12 || d == 0.0,
                    "surface {id}"
                );
                for i in 0..=12 {
                    for jj in 0..=12 {
                        let p0 = lo[0] + (hi[0] - lo[0]) * i as f64 / 12.0;
                        let p1 = lo[1] + (hi[1] - lo[1]) * jj as f64 / 12.0;
                        let x = o.point(sf, p0, (p0.cos(), p0.sin()), (p1.cos(), p1.sin()));
                        let dx = o.distance(x);
                        assert!(lower <= dx + 1e-12, "surface {id}: bound {lower} > {dx}");
                    }
                }
            }
        }
    }

    fn random_axes(rng: &mut Rng) -> [V3; 3] {
        // A uniform unit quaternion (Shoemake), as a rotation's columns.
        let (u1, u2, u3) = (rng.next(), rng.next(), rng.next());
        let tau = std::f64::consts::TAU;
        let (w, x, y, z) = (
            (1.0 - u1).sqrt() * (tau * u2).sin(),
            (1.0 - u1).sqrt() * (tau * u2).cos(),
            u1.sqrt() * (tau * u3).sin(),
            u1.sqrt() * (tau * u3).cos(),
        );
        [
            V3::new(
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y + w * z),
                2.0 * (x * z - w * y),
            ),
            V3::new(
                2.0 * (x * y - w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z + w * x),
            ),
            V3::new(
                2.0 * (x * z + w * y),
                2.0 * (y * z - w * x),
                1.0 - 2.0 * (x * x + y * y),
            ),
        ]
    }

    #[test]
    fn known_distances() {
        let o = Oracle::new(1.0);
        // Tip against tip along x, B turned half a turn about z.
        let flip = [V3::new(-1.0, 0.0, 0.0), V3::new(0.0, -1.0, 0.0), unit(2)];
        for (d, want) in [(2.5, 0.5), (2.1, 0.1), (2.0 + 1e-6, 1e-6)] {
            let j = o.judge(&Placement {
                centre: V3::new(d, 0.0, 0.0),
                axes: flip,
            });
            assert_eq!(j.verdict, Verdict::Apart, "{d}");
            assert!(
                j.lower <= want + 1e-12 && j.upper >= want - 1e-12,
                "{d}: {j:?}"
            );
            assert!(j.upper - j.lower <= 2e-10, "{d}: {j:?}");
        }
        let j = o.judge(&Placement {
            centre: V3::new(1.99, 0.0, 0.0),
            axes: flip,
        });
        assert_eq!(j.verdict, Verdict::Touching);
        // Coincident centres touch, whatever the rotation.
        let mut rng = Rng(5);
        let j = o.judge(&Placement {
            centre: V3::ZERO,
            axes: random_axes(&mut rng),
        });
        assert_eq!(j.verdict, Verdict::Touching);
    }

    #[test]
    fn inverse_placement_round_trips() {
        let mut rng = Rng(9);
        let s = Placement {
            centre: rng.point(1.0),
            axes: random_axes(&mut rng),
        };
        let p = rng.point(1.0);
        let back = s.inverse().judging_point(s.judging_point(p));
        assert!((back - p).norm() < 1e-14);
        assert!((s.body_point(s.judging_point(p)) - p).norm() < 1e-14);
    }
}
