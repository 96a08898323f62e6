//! Sphere trees (paper section 2; construction rules in docs/DESIGN.md "Sphere tree").
//!
//! One tree is built per scene and shared by every body (all bodies are the same shape). It is stored
//! flat and level-ordered: level 1 is index 0, then all level-2 spheres, and so on, and the children of
//! any sphere are one contiguous run. A traversal step that expands a sphere touches one short run of
//! 16-byte records, which is what makes a narrow phase over hundreds of thousands of pairs affordable.
//!
//! The leaves are always the paper's octree cells at level `depth`: the cells of the
//! 2^(depth-1)-per-axis grid over [-R, R]^3 whose interior meets the shape, each a sphere at its
//! centre with radius half its diagonal. Level 1 is one sphere at the origin with the smallest radius
//! that contains every leaf sphere: about 1.11R for the star, larger than R because leaf spheres stick
//! out of the shape. The inner levels are the octree's cells ([`TreeKind::Octree`]: each contains its
//! sub-cells' spheres exactly), the same cells with fitted spheres ([`TreeKind::Fitted`]), or the
//! star's parts and runs of their leaves with fitted spheres ([`TreeKind::Parts`]). The invariant the
//! traversal relies on is that every sphere contains all leaf spheres below it; with the same leaves,
//! every kind gives the same exact answers.

use glam::Vec4;
use serde::Serialize;

use crate::config::{MAX_DEPTH, TreeKind, Truth};
use crate::math::{LVec3, Vec3};
use crate::shape::Star;
use crate::star_contact::StarGeometry;
use crate::validate::ConfigError;

/// Flat, level-ordered sphere tree.
#[derive(Debug, Clone)]
pub struct SphereTree {
    /// Sphere `i`: body-frame centre in xyz, radius in w.
    spheres: Vec<Vec4>,
    /// Index of the first child of sphere `i` (meaningless for leaves).
    first_child: Vec<u32>,
    /// Number of children of sphere `i` (0 for leaves).
    child_count: Vec<u8>,
    /// `level_start[k]` is the index of the first sphere of level k+1; one extra entry at the end.
    level_start: Vec<u32>,
    /// The children of every inner sphere as one block of vectors (see [`Kids`]), by sphere index.
    kids: Vec<Kids>,
    depth: usize,
    kind: TreeKind,
    shape: Star,
    /// What a leaf overlap means: a collision (the paper), or a reason to test the stars.
    truth: Truth,
    /// The star's dimensions for the shape level ([`Truth::Shape`]).
    geometry: StarGeometry,
}

/// Spheres per vector in a [`Kids`] block.
pub const LANES: usize = 4;

/// The children of one sphere, structure-of-arrays: two vectors of four per coordinate and for the
/// radius, the lanes past the last child holding NaN (a NaN centre overlaps nothing, so unused
/// lanes need no mask). A step tests a sphere's children with one aligned load per coordinate and
/// no bounds check per child, where the 16-byte records would need a shuffle per sphere and axis.
#[derive(Debug, Clone, Copy)]
pub struct Kids {
    /// Index of the first child.
    pub first: u32,
    /// How many children there are (at most 8).
    pub count: u32,
    /// Centre x of children 0-3 and 4-7.
    pub x: [Vec4; 2],
    /// Centre y.
    pub y: [Vec4; 2],
    /// Centre z.
    pub z: [Vec4; 2],
    /// Radius.
    pub r: [Vec4; 2],
}

/// One sphere as exported for clients and offline checks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SphereRecord {
    /// Body-frame centre (scene units).
    pub center: [f64; 3],
    /// Radius (scene units).
    pub radius: f64,
    /// Level, 1 = root.
    pub level: u32,
    /// Index of the first child in the level-ordered list.
    pub first_child: u32,
    /// Number of children (0 for leaves).
    pub child_count: u32,
}

impl SphereTree {
    /// Build the paper's depth-`depth` octree of `shape` ([`TreeKind::Octree`]).
    pub fn build(shape: Star, depth: usize) -> Result<Self, ConfigError> {
        Self::build_kind(shape, depth, TreeKind::Octree)
    }

    /// Build the depth-`depth` tree of `shape` of the given kind. Every kind has the same leaves
    /// (the octree's cells at level `depth` that meet the shape, with their circumscribed
    /// spheres) and the same root (the smallest origin-centred sphere holding them), so a pair's
    /// exact answer is the same under each; they differ in the inner levels (docs/DESIGN.md
    /// "Sphere tree").
    pub fn build_kind(shape: Star, depth: usize, kind: TreeKind) -> Result<Self, ConfigError> {
        if !(1..=MAX_DEPTH).contains(&depth) {
            return Err(ConfigError::new(
                "scene.depth",
                depth,
                format!("must be in 1..={MAX_DEPTH}"),
            ));
        }
        let r = shape.radius;
        let (cells, parents) = octree_cells(&shape, depth);
        // The levels as (octree cell, parent within the level above) per node: the octree's
        // own, or regrouped by the star's parts (level 2 a part, whose cell is unused).
        let (cells, parents) = match kind {
            TreeKind::Parts if depth >= 3 => by_parts(&shape, &cells[depth - 1], depth),
            _ => (cells, parents),
        };
        let fitted = kind != TreeKind::Octree;
        // Leaves below each node: contiguous, since each level lists its nodes parent by parent.
        let mut below: Vec<Vec<(u32, u32)>> = vec![Vec::new(); depth];
        below[depth - 1] = (0..cells[depth - 1].len() as u32)
            .map(|i| (i, i + 1))
            .collect();
        for level in (1..depth).rev() {
            let mut ranges = vec![(u32::MAX, 0u32); cells[level - 1].len()];
            for (k, &p) in parents[level].iter().enumerate() {
                let (lo, hi) = below[level][k];
                let e = &mut ranges[p as usize];
                *e = (e.0.min(lo), e.1.max(hi));
            }
            below[level - 1] = ranges;
        }
        let cell_sphere = |level: usize, c: &[u32; 3]| -> (Vec3, f64) {
            let n = 1u32 << (level - 1);
            let w = 2.0 * r / f64::from(n);
            let centre = if level == 1 {
                Vec3::ZERO
            } else {
                Vec3::new(
                    -r + (f64::from(c[0]) + 0.5) * w,
                    -r + (f64::from(c[1]) + 0.5) * w,
                    -r + (f64::from(c[2]) + 0.5) * w,
                )
            };
            (centre, 0.5 * w * 3f64.sqrt())
        };
        let leaf_spheres: Vec<Vec4> = cells[depth - 1]
            .iter()
            .map(|c| {
                let (centre, radius) = cell_sphere(depth, c);
                Vec4::new(
                    centre.x as f32,
                    centre.y as f32,
                    centre.z as f32,
                    radius as f32,
                )
            })
            .collect();
        // Root: smallest origin-centred sphere containing every leaf sphere.
        let root_r = if depth == 1 {
            shape.radius
        } else {
            cells[depth - 1]
                .iter()
                .map(|c| {
                    let (centre, radius) = cell_sphere(depth, c);
                    centre.length() + radius
                })
                .fold(0.0, f64::max)
        };
        let root_reach = root_r;
        let mut spheres = Vec::new();
        let mut level_start = Vec::new();
        for (li, level_cells) in cells.iter().enumerate() {
            level_start.push(spheres.len() as u32);
            let level = li + 1;
            for (k, c) in level_cells.iter().enumerate() {
                let sphere = if level == depth {
                    leaf_spheres[k]
                } else if let Some(leaves) = below[li]
                    .get(k)
                    .filter(|_| fitted && level > 1)
                    .and_then(|&(lo, hi)| leaf_spheres.get(lo as usize..hi as usize))
                {
                    // The node's octree cell, where it is one (the parts tree's are not).
                    let cell = (kind == TreeKind::Fitted).then(|| cell_sphere(level, c));
                    fit(leaves, cell, root_reach)
                } else {
                    let (centre, radius) = cell_sphere(level, c);
                    Vec4::new(
                        centre.x as f32,
                        centre.y as f32,
                        centre.z as f32,
                        radius as f32,
                    )
                };
                spheres.push(sphere);
            }
        }
        level_start.push(spheres.len() as u32);
        // The root rounded up by one f32 ulp so the containment invariant survives the conversion
        // to f32.
        spheres[0].w = next_up(root_r as f32);
        // Children are contiguous because each level was generated parent by parent.
        let mut first_child = vec![0u32; spheres.len()];
        let mut child_count = vec![0u8; spheres.len()];
        for level in 2..=depth {
            let base = level_start[level - 1];
            let parent_base = level_start[level - 2];
            for (k, &p) in parents[level - 1].iter().enumerate() {
                let pi = (parent_base + p) as usize;
                if child_count[pi] == 0 {
                    first_child[pi] = base + k as u32;
                }
                if usize::from(child_count[pi]) == 2 * LANES {
                    return Err(ConfigError::new(
                        "scene.tree",
                        kind,
                        format!(
                            "a sphere of this tree at depth {depth} would have more than 8 children"
                        ),
                    ));
                }
                child_count[pi] += 1;
            }
        }
        let inner = level_start[depth - 1] as usize;
        let kids = (0..inner)
            .map(|i| {
                let (first, count) = (first_child[i] as usize, usize::from(child_count[i]));
                let lane = |c: usize, half: usize| {
                    Vec4::from_array(std::array::from_fn(|q| {
                        let k = half * LANES + q;
                        if k < count {
                            spheres[first + k][c]
                        } else {
                            f32::NAN
                        }
                    }))
                };
                Kids {
                    first: first as u32,
                    count: count as u32,
                    x: [lane(0, 0), lane(0, 1)],
                    y: [lane(1, 0), lane(1, 1)],
                    z: [lane(2, 0), lane(2, 1)],
                    r: [lane(3, 0), lane(3, 1)],
                }
            })
            .collect();
        Ok(Self {
            spheres,
            first_child,
            child_count,
            level_start,
            kids,
            depth,
            kind,
            shape,
            truth: Truth::LeafSpheres,
            geometry: StarGeometry::new(shape),
        })
    }

    /// Which hierarchy this is.
    pub fn kind(&self) -> TreeKind {
        self.kind
    }

    /// The tree with a truth: under [`Truth::Shape`] a pair whose leaves overlap is then tested
    /// on the stars ([`crate::star_contact`]) before it is called colliding. A tree is built with
    /// the paper's [`Truth::LeafSpheres`].
    pub fn with_truth(mut self, truth: Truth) -> Self {
        self.truth = truth;
        self
    }

    /// What "colliding" means for pairs traversed with this tree.
    #[inline]
    pub fn truth(&self) -> Truth {
        self.truth
    }

    /// The star's geometry for the shape level.
    #[inline]
    pub fn geometry(&self) -> &StarGeometry {
        &self.geometry
    }

    /// Sphere `i`: centre in xyz, radius in w.
    #[inline]
    pub fn sphere(&self, i: usize) -> Vec4 {
        self.spheres[i]
    }

    /// Body-frame centre of sphere `i`.
    #[inline]
    pub fn center(&self, i: usize) -> LVec3 {
        LVec3::from_vec4(self.spheres[i])
    }

    /// Children of sphere `i` as an index range (empty for leaves).
    #[inline]
    pub fn children(&self, i: usize) -> std::ops::Range<usize> {
        let f = self.first_child[i] as usize;
        f..f + self.child_count[i] as usize
    }

    /// The children of inner sphere `i` as vectors.
    ///
    /// # Panics
    /// If `i` is a leaf.
    #[inline]
    pub fn kids(&self, i: usize) -> &Kids {
        &self.kids[i]
    }

    /// Tree depth (number of levels).
    pub fn depth(&self) -> usize {
        self.depth
    }

    /// Total number of spheres.
    pub fn len(&self) -> usize {
        self.spheres.len()
    }

    /// Never true: a tree has at least its root.
    pub fn is_empty(&self) -> bool {
        self.spheres.is_empty()
    }

    /// Index range of level `level` (1-based).
    pub fn level_range(&self, level: usize) -> std::ops::Range<usize> {
        self.level_start[level - 1] as usize..self.level_start[level] as usize
    }

    /// Index range of the leaves.
    pub fn leaves(&self) -> std::ops::Range<usize> {
        self.level_range(self.depth)
    }

    /// Number of spheres per level, level 1 first (1, 8, 32, 80 for the octree at depth 4; 1, 7,
    /// 20, 80 for the parts tree).
    pub fn spheres_per_level(&self) -> Vec<usize> {
        (1..=self.depth)
            .map(|l| self.level_range(l).len())
            .collect()
    }

    /// Root radius: the half-size of every body's fixed bounding box.
    pub fn root_radius(&self) -> f64 {
        f64::from(self.spheres[0].w)
    }

    /// The shape the tree approximates.
    pub fn shape(&self) -> Star {
        self.shape
    }

    /// Level-ordered sphere records for export.
    pub fn records(&self) -> Vec<SphereRecord> {
        (1..=self.depth)
            .flat_map(|level| self.level_range(level).map(move |i| (level, i)))
            .map(|(level, i)| {
                let s = self.spheres[i];
                SphereRecord {
                    center: [f64::from(s.x), f64::from(s.y), f64::from(s.z)],
                    radius: f64::from(s.w),
                    level: level as u32,
                    first_child: self.first_child[i],
                    child_count: u32::from(self.child_count[i]),
                }
            })
            .collect()
    }

    /// Panic unless the structural invariants hold (used by tests): level order, contiguous child
    /// runs on the next level, every sphere containing every leaf below it.
    pub fn assert_well_formed(&self) {
        assert_eq!(self.level_range(1).len(), 1);
        for level in 1..self.depth {
            for i in self.level_range(level) {
                let ch = self.children(i);
                assert!(
                    !ch.is_empty(),
                    "sphere {i} at level {level} has no children"
                );
                let next = self.level_range(level + 1);
                assert!(
                    ch.start >= next.start && ch.end <= next.end,
                    "children of {i} not on next level"
                );
            }
        }
        for level in 1..=self.depth {
            for i in self.level_range(level) {
                let s = self.spheres[i];
                let mut stack = vec![i];
                while let Some(j) = stack.pop() {
                    if self.children(j).is_empty() {
                        let l = self.spheres[j];
                        let reach = (LVec3::from_vec4(l) - LVec3::from_vec4(s)).length() + l.w;
                        assert!(
                            reach <= s.w * (1.0 + 4.0 * f32::EPSILON),
                            "sphere {i} misses leaf {j}: {reach} > {}",
                            s.w
                        );
                    }
                    stack.extend(self.children(j));
                }
            }
        }
    }
}

/// Per level, the octree's cells (integer coordinates on the level's grid) whose interior meets
/// the shape, and each cell's parent (its index in the level above), listed parent by parent.
/// Cells are kept as integers so that no rounding decides which cell is which.
#[allow(clippy::type_complexity)]
fn octree_cells(shape: &Star, depth: usize) -> (Vec<Vec<[u32; 3]>>, Vec<Vec<u32>>) {
    let r = shape.radius;
    let mut cells: Vec<Vec<[u32; 3]>> = vec![vec![[0, 0, 0]]];
    let mut parents: Vec<Vec<u32>> = vec![vec![]];
    for level in 2..=depth {
        let n = 1u32 << (level - 1);
        let w = 2.0 * r / f64::from(n);
        let mut next = Vec::new();
        let mut next_parent = Vec::new();
        for (pi, cell) in cells[level - 2].iter().enumerate() {
            for child in 0..8u32 {
                let c = [
                    cell[0] * 2 + (child & 1),
                    cell[1] * 2 + ((child >> 1) & 1),
                    cell[2] * 2 + (child >> 2),
                ];
                let lo = Vec3::new(
                    -r + f64::from(c[0]) * w,
                    -r + f64::from(c[1]) * w,
                    -r + f64::from(c[2]) * w,
                );
                if shape.cell_intersects(lo, lo + Vec3::splat(w)) {
                    next.push(c);
                    next_parent.push(pi as u32);
                }
            }
        }
        cells.push(next);
        parents.push(next_parent);
    }
    // A cell the shape meets may have no sub-cell whose interior does (at depth 6, by rounding
    // at the cells' faces): it holds no leaf, can never lead to a collision, and is dropped, so
    // that every inner sphere has children.
    for li in (1..depth.saturating_sub(1)).rev() {
        let mut has_child = vec![false; cells[li].len()];
        for &p in &parents[li + 1] {
            has_child[p as usize] = true;
        }
        if has_child.iter().all(|&h| h) {
            continue;
        }
        let mut new_index = vec![u32::MAX; cells[li].len()];
        let mut kept = 0u32;
        for (k, &h) in has_child.iter().enumerate() {
            if h {
                new_index[k] = kept;
                kept += 1;
            }
        }
        fn keep<T: Copy>(v: &[T], has_child: &[bool]) -> Vec<T> {
            v.iter()
                .zip(has_child)
                .filter(|(_, h)| **h)
                .map(|(x, _)| *x)
                .collect()
        }
        cells[li] = keep(&cells[li], &has_child);
        parents[li] = keep(&parents[li], &has_child);
        for p in &mut parents[li + 1] {
            *p = new_index[*p as usize];
        }
    }
    (cells, parents)
}

/// The star's part a leaf cell (integer coordinates at `depth`) is grouped under: 0 the core
/// (every coordinate of its centre within the core's radius), else the spike its centre points
/// along most (1 + 2 x axis, + 1 for the negative side; the first axis of equals).
fn part_of(shape: &Star, depth: usize, c: &[u32; 3]) -> u32 {
    let r = shape.radius;
    let w = 2.0 * r / f64::from(1u32 << (depth - 1));
    let centre = c.map(|k| -r + (f64::from(k) + 0.5) * w);
    let (mut axis, mut reach) = (0, centre[0].abs());
    for (k, v) in centre.iter().enumerate().skip(1) {
        if v.abs() > reach {
            (axis, reach) = (k, v.abs());
        }
    }
    if reach < shape.core_radius {
        0
    } else {
        1 + 2 * axis as u32 + u32::from(centre[axis] < 0.0)
    }
}

/// The levels of the parts tree over the octree's leaf cells `leaves`: level 2 the parts that
/// have leaves (in part order), then each node's leaves split into groups, level by level, down
/// to the leaves themselves at `depth`. A node's leaves are sorted along the axis they spread
/// most on (then by position, so the order is fixed) and cut into as few runs of about equal
/// length as leave at most four children a node where the levels below allow it: the descent
/// tests a sphere's children four at a time (eight with AVX2), so a node with one or two
/// children costs a step as much as one with four. Grouped by octree cells instead, a spike's
/// leaves fell one or two to a cell, and the tree took more time per pair than the octree for
/// fewer tests. Runs of up to eight took 0.62x the octree's exact narrow phase under the leaf
/// truth against 0.64x for four, and 0.99x against 0.985x under the shape truth (two runs,
/// each interleaved, at N = 10,000): within the runs' noise, and four suits both kernels. Returns per level the
/// nodes' cells (only the leaves' are used) and parents, as [`octree_cells`] does.
#[allow(clippy::type_complexity)]
fn by_parts(
    shape: &Star,
    leaves: &[[u32; 3]],
    depth: usize,
) -> (Vec<Vec<[u32; 3]>>, Vec<Vec<u32>>) {
    let mut groups: Vec<Vec<u32>> = Vec::new();
    for (i, c) in leaves.iter().enumerate() {
        let p = part_of(shape, depth, c) as usize;
        if groups.len() <= p {
            groups.resize(p + 1, Vec::new());
        }
        groups[p].push(i as u32);
    }
    groups.retain(|g| !g.is_empty());
    let mut cells: Vec<Vec<[u32; 3]>> = vec![vec![[0, 0, 0]], vec![[0, 0, 0]; groups.len()]];
    let mut parents: Vec<Vec<u32>> = vec![vec![], vec![0; groups.len()]];
    for level in 3..=depth {
        let below = depth - level + 1;
        let mut next = Vec::new();
        let mut next_parent = Vec::new();
        for (p, group) in groups.iter_mut().enumerate() {
            sort_along_spread(group, leaves);
            let runs = if below == 1 {
                group.len()
            } else {
                group
                    .len()
                    .div_ceil(LANES.pow(below as u32 - 1))
                    .clamp(1, 2 * LANES)
            };
            let (len, extra) = (group.len() / runs, group.len() % runs);
            let mut at = 0;
            for k in 0..runs {
                let take = len + usize::from(k < extra);
                next.push(group[at..at + take].to_vec());
                next_parent.push(p as u32);
                at += take;
            }
        }
        groups = next;
        cells.push(if level == depth {
            groups.iter().map(|g| leaves[g[0] as usize]).collect()
        } else {
            vec![[0, 0, 0]; groups.len()]
        });
        parents.push(next_parent);
    }
    (cells, parents)
}

/// Sort leaf indices along the axis their cells spread most on, then by position.
fn sort_along_spread(group: &mut [u32], leaves: &[[u32; 3]]) {
    let spread = |axis: usize| {
        let v = group.iter().map(|&i| leaves[i as usize][axis]);
        v.clone().max().unwrap_or(0) - v.min().unwrap_or(0)
    };
    let axis = (0..3)
        .max_by_key(|&a| (spread(a), std::cmp::Reverse(a)))
        .unwrap_or(0);
    group.sort_unstable_by_key(|&i| {
        let c = leaves[i as usize];
        (c[axis], c[(axis + 1) % 3], c[(axis + 2) % 3])
    });
}

/// The inner sphere over `leaves` (all of one radius) that the other body's root overlaps least
/// often. A pair is a candidate when its roots overlap, so the other body's centre lies within
/// twice the root's radius `root_r` of this body's; a sphere (c, r) is tested against the other
/// root, which overlaps it where that centre lies within r + `root_r` of c. The sphere kept is
/// the one, among candidates that hold every leaf, for which that region's volume inside the
/// candidate ball is least: the smallest enclosing ball of the leaves (Badoiu and Clarkson's
/// iteration) is not it, since moving a sphere outwards, away from the body's centre, puts part
/// of its region where no candidate's centre can be. The candidates are that ball's centre moved
/// along the line from the body's centre, the octree cell's centre (`cell`, where the node has
/// one) and points between the two. Each radius is computed from the f32 centre and rounded up,
/// so that containment holds exactly.
fn fit(leaves: &[Vec4], cell: Option<(Vec3, f64)>, root_r: f64) -> Vec4 {
    let at = |s: &Vec4| Vec3::new(f64::from(s.x), f64::from(s.y), f64::from(s.z));
    let Some(first) = leaves.first() else {
        return Vec4::ZERO;
    };
    let farthest = |c: Vec3| {
        leaves
            .iter()
            .map(&at)
            .max_by(|a, b| {
                (*a - c)
                    .length_squared()
                    .total_cmp(&(*b - c).length_squared())
            })
            .unwrap_or(c)
    };
    let mut ball = at(first);
    for k in 1..=FIT_STEPS {
        let q = farthest(ball);
        ball += (q - ball) / f64::from(k + 1);
    }
    let holding = |c: Vec3| -> Vec4 {
        let cf = Vec4::new(c.x as f32, c.y as f32, c.z as f32, 0.0);
        let c = at(&cf);
        let reach = leaves
            .iter()
            .map(|s| (at(s) - c).length() + f64::from(s.w))
            .fold(0.0, f64::max);
        Vec4::new(
            cf.x,
            cf.y,
            cf.z,
            next_up(next_up((reach * (1.0 + 1e-7)) as f32)),
        )
    };
    let exposure = |s: &Vec4| lens_volume(at(s).length(), f64::from(s.w) + root_r, 2.0 * root_r);
    let outward = ball.normalize_or_zero();
    let shifted = (-4..=12).map(|k| ball + outward * (f64::from(k) * FIT_SHIFT * root_r));
    let towards_cell = cell.into_iter().flat_map(|(centre, _)| {
        (0..=4).map(move |k| ball + (centre - ball) * (f64::from(k) / 4.0))
    });
    // The first of equals: the ball itself, then the candidates in order.
    std::iter::once(ball)
        .chain(shifted)
        .chain(towards_cell)
        .map(|c| {
            let s = holding(c);
            (exposure(&s), s)
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map_or_else(|| holding(ball), |(_, s)| s)
}

/// Volume of the intersection of two balls of radii `r1` and `r2` whose centres are `d` apart.
fn lens_volume(d: f64, r1: f64, r2: f64) -> f64 {
    let ball = |r: f64| 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
    if d >= r1 + r2 {
        0.0
    } else if d <= (r1 - r2).abs() {
        ball(r1.min(r2))
    } else {
        std::f64::consts::PI
            * (r1 + r2 - d).powi(2)
            * (d * d + 2.0 * d * (r1 + r2) - 3.0 * (r1 - r2).powi(2))
            / (12.0 * d)
    }
}

/// Iterations of [`fit`]'s smallest enclosing ball: within about 1/sqrt(k) of its radius, a few
/// tenths of a percent here.
const FIT_STEPS: u32 = 400;

/// Step of [`fit`]'s outward candidates, as a share of the root's radius.
const FIT_SHIFT: f64 = 0.025;

/// The next representable f32 above `x` (x finite, positive).
fn next_up(x: f32) -> f32 {
    f32::from_bits(x.to_bits() + 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    #[test]
    fn paper_tree_has_1_8_32_80_spheres_and_is_well_formed() {
        let t = SphereTree::build(Star::new(0.2), 4).expect("depth 4");
        assert_eq!(t.spheres_per_level(), vec![1, 8, 32, 80]);
        t.assert_well_formed();
        let ratio = t.root_radius() / 0.2;
        assert!((1.05..1.2).contains(&ratio), "root radius {ratio} R");
    }

    #[test]
    fn every_kind_at_every_depth_is_well_formed_over_the_same_leaves_and_root() {
        let shape = Star::new(0.2);
        for depth in 1..=MAX_DEPTH {
            let octree = SphereTree::build(shape, depth).expect("octree");
            let mut want: Vec<[u32; 4]> = octree
                .leaves()
                .map(|i| octree.sphere(i).to_array().map(f32::to_bits))
                .collect();
            want.sort_unstable();
            for kind in TreeKind::ALL {
                let t = SphereTree::build_kind(shape, depth, kind).expect("builds");
                t.assert_well_formed();
                assert_eq!(t.kind(), kind);
                assert_eq!(t.depth(), depth);
                let mut got: Vec<[u32; 4]> = t
                    .leaves()
                    .map(|i| t.sphere(i).to_array().map(f32::to_bits))
                    .collect();
                got.sort_unstable();
                assert_eq!(
                    got, want,
                    "{kind} at depth {depth}: not the octree's leaves"
                );
                assert_eq!(
                    t.sphere(0),
                    octree.sphere(0),
                    "{kind} at depth {depth}: root"
                );
            }
        }
    }

    /// The fitted kinds' inner spheres are no larger than the octree's cells: what saves tests.
    /// At the paper's depth the parts tree has the core and six spikes at level 2.
    #[test]
    fn fitted_inner_spheres_are_tighter_and_the_parts_are_the_core_and_six_spikes() {
        let shape = Star::new(1.0);
        let reach = |t: &SphereTree, level: usize| -> f64 {
            t.level_range(level)
                .map(|i| {
                    let s = t.sphere(i);
                    f64::from(s.w)
                })
                .sum::<f64>()
                / t.level_range(level).len() as f64
        };
        let octree = SphereTree::build(shape, 4).expect("octree");
        let fitted = SphereTree::build_kind(shape, 4, TreeKind::Fitted).expect("fitted");
        let parts = SphereTree::build_kind(shape, 4, TreeKind::Parts).expect("parts");
        assert_eq!(parts.spheres_per_level()[1], 7);
        assert_eq!(fitted.spheres_per_level(), octree.spheres_per_level());
        // An octant's cell sphere is already the one B's root meets least (it lies outwards);
        // one level down the fitted spheres are smaller.
        assert!(reach(&fitted, 2) <= reach(&octree, 2) * (1.0 + 1e-6));
        assert!(reach(&fitted, 3) < reach(&octree, 3));
        // Each spike's sphere is well inside an octant's 0.87R.
        for i in parts.level_range(2) {
            let w = f64::from(parts.sphere(i).w);
            assert!(w < 0.7, "part sphere {i}: radius {w}");
        }
    }

    #[test]
    fn every_depth_builds_and_is_well_formed() {
        for depth in 1..=MAX_DEPTH {
            let t = SphereTree::build(Star::new(1.0), depth).expect("valid depth");
            t.assert_well_formed();
            assert_eq!(t.spheres_per_level().len(), depth);
        }
        assert!(SphereTree::build(Star::new(1.0), 0).is_err());
        assert!(SphereTree::build(Star::new(1.0), 7).is_err());
    }

    #[test]
    fn leaves_cover_a_dense_sample_of_the_shape() {
        for depth in [2, 4, 5] {
            let shape = Star::new(0.2);
            let t = SphereTree::build(shape, depth).expect("tree");
            let mut rng = Rng::new(9);
            let mut inside = 0;
            for _ in 0..200_000 {
                let p = Vec3::new(
                    rng.range(-0.2, 0.2),
                    rng.range(-0.2, 0.2),
                    rng.range(-0.2, 0.2),
                );
                if !shape.contains(p) {
                    continue;
                }
                inside += 1;
                let q = LVec3::new(p.x as f32, p.y as f32, p.z as f32);
                let covered = t.leaves().any(|i| {
                    let s = t.sphere(i);
                    (q - LVec3::from_vec4(s)).length_squared() <= s.w * s.w * (1.0 + 1e-5)
                });
                assert!(
                    covered,
                    "point {p} of the shape not covered at depth {depth}"
                );
            }
            assert!(inside > 5_000);
        }
    }
}
