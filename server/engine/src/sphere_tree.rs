//! Octree sphere trees (paper section 2; construction rule from DESIGN.md "Sphere tree").
//!
//! One tree is built per scene and shared by every body (all bodies are the same shape). It is stored
//! flat and level-ordered: level 1 is index 0, then all level-2 spheres, and so on, and the children of
//! any sphere are one contiguous run. A traversal step that expands a sphere touches one short run of
//! 16-byte records, which is what makes a narrow phase over hundreds of thousands of pairs affordable.
//!
//! Level k (2..=depth) holds the cells of the 2^(k-1)-per-axis grid over [-R, R]^3 whose interior meets
//! the shape; each cell gives a sphere at its centre with radius half its diagonal, so it contains its
//! sub-cells' spheres exactly (the offset to a child centre is a quarter diagonal, the child radius
//! another quarter). Level 1 is one sphere at the origin with the smallest radius that contains every
//! leaf sphere: about 1.11R for the star, larger than R because leaf spheres stick out of the shape.
//! The invariant the traversal relies on is that every sphere contains all leaf spheres below it.

use glam::Vec4;
use serde::Serialize;

use crate::config::{MAX_DEPTH, Truth};
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
    /// Build the depth-`depth` tree of `shape`.
    pub fn build(shape: Star, depth: usize) -> Result<Self, ConfigError> {
        if !(1..=MAX_DEPTH).contains(&depth) {
            return Err(ConfigError::new(
                "scene.depth",
                depth,
                format!("must be in 1..={MAX_DEPTH}"),
            ));
        }
        let r = shape.radius;
        // Cells are kept as integer coordinates on the level's grid so that no rounding decides
        // which cell is which; positions are computed from them only for the shape test.
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
        let mut spheres = Vec::new();
        let mut level_start = Vec::new();
        let mut centres_f64 = Vec::new();
        for (li, level_cells) in cells.iter().enumerate() {
            level_start.push(spheres.len() as u32);
            let level = li + 1;
            let n = 1u32 << (level - 1);
            let w = 2.0 * r / f64::from(n);
            for c in level_cells {
                let centre = if level == 1 {
                    Vec3::ZERO
                } else {
                    Vec3::new(
                        -r + (f64::from(c[0]) + 0.5) * w,
                        -r + (f64::from(c[1]) + 0.5) * w,
                        -r + (f64::from(c[2]) + 0.5) * w,
                    )
                };
                let radius = 0.5 * w * 3f64.sqrt();
                centres_f64.push((centre, radius));
                spheres.push(Vec4::new(
                    centre.x as f32,
                    centre.y as f32,
                    centre.z as f32,
                    radius as f32,
                ));
            }
        }
        level_start.push(spheres.len() as u32);
        // Root: smallest origin-centred sphere containing every leaf sphere. Rounded up by one f32
        // ulp so the containment invariant survives the conversion to f32.
        let leaves = level_start[depth - 1] as usize..spheres.len();
        let root_r = if depth == 1 {
            shape.radius
        } else {
            centres_f64[leaves]
                .iter()
                .map(|(c, rad)| c.length() + rad)
                .fold(0.0, f64::max)
        };
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
            shape,
            truth: Truth::LeafSpheres,
            geometry: StarGeometry::new(shape),
        })
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

    /// Number of spheres per level, level 1 first (1, 8, 32, 80 at depth 4).
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
