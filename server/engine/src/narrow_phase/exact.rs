//! Exact answers, off the budget: a pair's separation (the audit's true gap), under the leaf truth
//! and on the drawn shape, and brute-force collision for tests.

use super::*;

/// Body `b`'s pose in body `a`'s frame, in f64 from the bodies' orientations and positions: the
/// shape level decides touching at a tolerance of 1e-9 R, beyond the f32 frames of the descent.
pub fn shape_pose(world: &World, a: usize, b: usize) -> Pose {
    let qa = world.orientation[a].conjugate();
    Pose {
        rotation: glam::DMat3::from_quat(qa * world.orientation[b]),
        translation: qa * (world.position[b] - world.position[a]),
    }
}

/// The truth on the shape for bodies `a` and `b`: their signed distance (the gap, or minus the
/// penetration depth) and the two facing points of the gap in world coordinates (both the
/// contact point when they touch).
pub fn shape_separation(tree: &SphereTree, world: &World, a: usize, b: usize) -> (f64, Vec3, Vec3) {
    let c = tree.geometry().contact(&shape_pose(world, a, b));
    let (pa, qa) = (world.position[a], world.orientation[a]);
    let to_world = |p: Vec3| pa + qa * p;
    match c {
        Contact::Touching { point, depth, .. } => (-depth, to_world(point), to_world(point)),
        Contact::Apart {
            distance,
            point_a,
            point_b,
        } => (distance, to_world(point_a), to_world(point_b)),
    }
}

/// The exact answer by brute force: whether any leaf sphere of `a` overlaps any leaf sphere of `b`
/// (DESIGN.md "Exact answer"), with the same kernel and the same relative frame as the traversal.
/// Under the shape truth, the leaves' answer and then the stars' own test.
pub fn brute_force_colliding(tree: &SphereTree, world: &World, a: usize, b: usize) -> bool {
    let f = PairFrame::new(world, a, b);
    let leaves = tree.leaves().any(|j| {
        let sb = tree.sphere(j);
        let cb = f.map(sb);
        tree.leaves()
            .any(|i| spheres_overlap(tree.sphere(i), cb, sb.w))
    });
    match tree.truth() {
        Truth::LeafSpheres => leaves,
        Truth::Shape => leaves && tree.geometry().intersects(&shape_pose(world, a, b)),
    }
}

/// True separation of two bodies' leaf-sphere sets: the smallest `|ca - cb| - ra - rb` over leaf
/// pairs (<= 0 when they collide), with the closest pair's centres in world coordinates.
///
/// Branch and bound over both trees, nearest sphere pair first: a parent contains its leaves, so its
/// distance is a lower bound for every leaf pair below it, and a subtree whose bound is no better than
/// the best leaf pair found is skipped. This gives the same minimum as the full leaf-by-leaf scan at
/// a small fraction of its cost. `stack` is scratch space, reused between calls.
pub fn separation(
    tree: &SphereTree,
    world: &World,
    a: usize,
    b: usize,
    stack: &mut Vec<(f32, u16, u16, u8, u8)>,
) -> (f64, Vec3, Vec3) {
    let f = PairFrame::new(world, a, b);
    let dist = |sa: usize, sb: usize| -> f32 {
        let (x, y) = (tree.sphere(sa), tree.sphere(sb));
        (LVec3::from_vec4(x) - f.map(y)).length() - x.w - y.w
    };
    let depth = tree.depth() as u8;
    let mut best = (f32::INFINITY, 0u16, 0u16);
    stack.clear();
    stack.push((dist(0, 0), 0, 0, 1, 1));
    let mut kids = [(0f32, 0u16, 0u16); 8];
    while let Some((bound, sa, sb, la, lb)) = stack.pop() {
        if bound >= best.0 {
            continue;
        }
        if la == depth && lb == depth {
            best = (bound, sa, sb);
            continue;
        }
        let descend_a = la < depth;
        let range = tree.children(if descend_a { sa } else { sb } as usize);
        let kids = &mut kids[..range.len()];
        for (k, c) in kids.iter_mut().zip(range) {
            *k = if descend_a {
                (dist(c, sb as usize), c as u16, sb)
            } else {
                (dist(sa as usize, c), sa, c as u16)
            };
        }
        // Farthest first onto the stack, so the nearest child is explored next.
        kids.sort_unstable_by(|x, y| y.0.total_cmp(&x.0));
        let (na, nb) = if descend_a {
            (la + 1, lb)
        } else {
            (la, lb + 1)
        };
        stack.extend(
            kids.iter()
                .filter(|k| k.0 < best.0)
                .map(|&(d, x, y)| (d, x, y, na, nb)),
        );
    }
    let pa = world.position[a];
    let basis = glam::Mat3::from(world.basis[a]).as_dmat3();
    let ca = pa + basis * tree.center(best.1 as usize).as_dvec3();
    let cb = pa + basis * f.map(tree.sphere(best.2 as usize)).as_dvec3();
    (f64::from(best.0), ca, cb)
}
