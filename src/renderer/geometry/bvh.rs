//! Bounding volume hierarchies: a four-wide BVH (a QBVH, Dammertz et al. 2008; Wald et al.
//! 2008) traversed one ray at a time with the four child boxes tested in SIMD lanes.
//! Only triangle meshes and hair fibres use one; analytic spheres and quads are few and
//! tested directly.
//!
//! obvhs builds the tree (PLOC and reinsertion, as a binary BVH with at most four
//! primitives per leaf); it is then collapsed to four children per node, nearest child
//! visited first, and a leaf's primitives are tested together (`TrianglePack`,
//! `FibrePack`). obvhs' own compressed wide BVH (CWBVH) is laid out for GPUs: on a CPU core
//! its traversal decodes quantised boxes at every node and tests one primitive at a time.
//! Measured against it (`src/renderer/PROFILE.md`): renders of the 115k-triangle knot 1.3
//! to 1.46 times as many paths per CPU-second, with the same image bit for bit.

use super::Ray;
use glam::{BVec4A, Vec4};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb;
use obvhs::bvh2::Bvh2;
use std::ops::Range;
use std::time::Duration;

/// Primitives per leaf at most, and the slots every leaf occupies: a leaf's primitives sit
/// in slots `4k .. 4k + count`, so a caller can store them as one four-lane pack.
pub const LEAF_SLOTS: usize = 4;

/// A child reference with this bit set is a leaf: `LEAF | pack << 2 | (count − 1)`.
const LEAF: u32 = 1 << 31;

/// Entries of the traversal stack kept in place, on the call's own stack frame. A
/// four-wide tree pushes at most three per level, and PLOC's trees of a million primitives
/// stay within 21 four-wide levels; a deeper tree ([`Bvh::stack_bound`]) traverses with a
/// stack on the heap instead.
const IN_PLACE: usize = 64;

/// A traversal stack of nodes still to visit.
trait Stack<T> {
    fn push(&mut self, item: T);
    fn pop(&mut self) -> Option<T>;
}

/// A stack of at most [`IN_PLACE`] entries in an array. A `SmallVec` asks at every push
/// and pop where its data lives; this has a bounds check that never fails (the tree's
/// bound was checked before), and mesh and hair renders trace 3–10 % more paths per
/// CPU-second with it.
struct InPlace<T> {
    items: [T; IN_PLACE],
    len: usize,
}

impl<T: Copy + Default> InPlace<T> {
    #[inline(always)]
    fn new() -> Self {
        Self {
            items: [T::default(); IN_PLACE],
            len: 0,
        }
    }
}

impl<T: Copy> Stack<T> for InPlace<T> {
    #[inline(always)]
    fn push(&mut self, item: T) {
        self.items[self.len] = item;
        self.len += 1;
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<T> {
        self.len = self.len.checked_sub(1)?;
        Some(self.items[self.len])
    }
}

impl<T> Stack<T> for Vec<T> {
    #[inline(always)]
    fn push(&mut self, item: T) {
        Vec::push(self, item);
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<T> {
        Vec::pop(self)
    }
}

/// One node: the boxes of up to four children as structure-of-arrays lanes. An unused lane
/// has an empty box at +∞ that no ray enters.
#[derive(Clone, Copy, Debug)]
struct Node {
    lo: [Vec4; 3],
    hi: [Vec4; 3],
    child: [u32; 4],
}

/// A four-wide BVH over primitives given by their bounding boxes. Its leaves refer to
/// primitives by slot: callers store their primitives in slot order ([`Bvh::by_slot`]), so
/// that a leaf's slots index them directly.
pub struct Bvh {
    nodes: Vec<Node>,
    /// For each slot, the input primitive stored there (`u32::MAX`: padding).
    order: Vec<u32>,
    /// The most entries a traversal's stack can hold: at a node of `c` children, `c − 1`
    /// wait while one is visited (all `c` for a moment in [`Bvh::any`]), over the
    /// deepest such chain. Above [`IN_PLACE`], traversals keep their stack on the heap.
    stack_bound: usize,
}

/// A ray prepared for box tests: origin and reciprocal direction in every lane.
struct BoxRay {
    origin: [Vec4; 3],
    inv_dir: [Vec4; 3],
}

impl BoxRay {
    fn new(ray: &Ray) -> Self {
        // A zero component would make 0 · ∞ = NaN on a slab through the origin; a tiny one
        // gives the same verdicts (±huge instead of ±∞).
        let inv = |d: f32| {
            1.0 / if d.abs() < 1e-30 {
                1e-30f32.copysign(d)
            } else {
                d
            }
        };
        let o = ray.origin;
        let d = ray.dir;
        Self {
            origin: [Vec4::splat(o.x), Vec4::splat(o.y), Vec4::splat(o.z)],
            inv_dir: [
                Vec4::splat(inv(d.x)),
                Vec4::splat(inv(d.y)),
                Vec4::splat(inv(d.z)),
            ],
        }
    }

    /// Per lane, the entry distance into the child's box, and which lanes the ray enters
    /// before `t_max`. The exit distance is widened by 1 + 2γ₃ (Ize 2013, "Robust BVH Ray
    /// Traversal"), so that rounding never culls a box the ray touches. The comparison is
    /// strict so that an unused lane (a box at +∞, entered at +∞) stays out even when
    /// `t_max` is +∞; a box entered and left at the same positive distance is still
    /// entered, thanks to the widening.
    #[inline(always)]
    fn enter(&self, node: &Node, t_max: f32) -> (Vec4, BVec4A) {
        let mut near = Vec4::ZERO;
        let mut far = Vec4::splat(t_max);
        for axis in 0..3 {
            let t0 = (node.lo[axis] - self.origin[axis]) * self.inv_dir[axis];
            let t1 = (node.hi[axis] - self.origin[axis]) * self.inv_dir[axis];
            near = near.max(t0.min(t1));
            far = far.min(t0.max(t1));
        }
        (near, near.cmplt(far * 1.000_000_4))
    }
}

impl Bvh {
    /// Builds a BVH over `boxes` (at least one).
    pub fn build(boxes: &[Aabb]) -> Self {
        let params = BvhBuildParams {
            max_prims_per_leaf: LEAF_SLOTS as u32,
            ..BvhBuildParams::medium_build()
        };
        let bvh2 = obvhs::bvh2::builder::build_bvh2(boxes, params, &mut Duration::default());
        let mut bvh = Self {
            nodes: Vec::new(),
            order: Vec::new(),
            stack_bound: 1,
        };
        let root = &bvh2.nodes[0];
        if root.is_leaf() {
            // A single leaf still gets a node above it, so traversal always starts at one.
            bvh.nodes.push(Node {
                lo: [Vec4::INFINITY; 3],
                hi: [Vec4::INFINITY; 3],
                child: [u32::MAX; 4],
            });
            let leaf = bvh.leaf(&bvh2, 0);
            bvh.set_lane(0, 0, &root.aabb, leaf);
        } else {
            bvh.stack_bound = bvh.collapse(&bvh2, 0).1;
        }
        bvh
    }

    /// `items` (one per input primitive) in slot order, with `padding` in the slots after a
    /// leaf of fewer than [`LEAF_SLOTS`] primitives.
    pub fn by_slot<T: Copy>(&self, items: &[T], padding: T) -> Vec<T> {
        self.order
            .iter()
            .map(|&i| items.get(i as usize).copied().unwrap_or(padding))
            .collect()
    }

    /// Adds the leaf `index` of `bvh2`: its primitives in the next free slots, padded to
    /// [`LEAF_SLOTS`]. Returns its child reference.
    fn leaf(&mut self, bvh2: &Bvh2, index: usize) -> u32 {
        let node = &bvh2.nodes[index];
        let first = node.first_index as usize;
        let count = node.prim_count as usize;
        let pack = self.order.len() / LEAF_SLOTS;
        self.order
            .extend_from_slice(&bvh2.primitive_indices[first..first + count]);
        self.order.resize((pack + 1) * LEAF_SLOTS, u32::MAX);
        LEAF | (pack as u32) << 2 | (count as u32 - 1)
    }

    /// Adds the interior node `index` of `bvh2` and its subtree, opening the children with
    /// the largest surface area until it has four (or only leaves are left). Returns the
    /// new node's index and the stack bound of its subtree (see [`Bvh::stack_bound`]).
    fn collapse(&mut self, bvh2: &Bvh2, index: usize) -> (u32, usize) {
        let first = bvh2.nodes[index].first_index as usize;
        let mut children = vec![first, first + 1];
        while children.len() < 4 {
            let widest = children
                .iter()
                .enumerate()
                .filter(|(_, c)| !bvh2.nodes[**c].is_leaf())
                .max_by(|a, b| {
                    let area = |c: usize| bvh2.nodes[c].aabb.half_area();
                    area(*a.1).total_cmp(&area(*b.1))
                })
                .map(|(i, _)| i);
            let Some(i) = widest else { break };
            let opened = bvh2.nodes[children.swap_remove(i)].first_index as usize;
            children.extend([opened, opened + 1]);
        }
        let this = self.nodes.len();
        self.nodes.push(Node {
            lo: [Vec4::INFINITY; 3],
            hi: [Vec4::INFINITY; 3],
            child: [u32::MAX; 4],
        });
        // The largest bound below a child, or 1: a leaf child itself is one entry.
        let mut below = 1;
        let count = children.len();
        for (lane, c) in children.into_iter().enumerate() {
            let child = if bvh2.nodes[c].is_leaf() {
                self.leaf(bvh2, c)
            } else {
                let (child, bound) = self.collapse(bvh2, c);
                below = below.max(bound);
                child
            };
            self.set_lane(this, lane, &bvh2.nodes[c].aabb, child);
        }
        (this as u32, count - 1 + below)
    }

    /// Puts `child` with its box in `lane` of `node`. The box is widened by a few ulps of
    /// its coordinates so that a ray running exactly in one of its faces (an axis-aligned
    /// ray along a mesh's edge, whose direction has a zero component) is inside it, not on
    /// its boundary, where the slab test's 0 · ∞ would decide.
    fn set_lane(&mut self, node: usize, lane: usize, aabb: &Aabb, child: u32) {
        let n = &mut self.nodes[node];
        for axis in 0..3 {
            let (lo, hi) = (aabb.min[axis], aabb.max[axis]);
            let widen = 1e-6 * lo.abs().max(hi.abs()) + 1e-30;
            n.lo[axis][lane] = lo - widen;
            n.hi[axis][lane] = hi + widen;
        }
        n.child[lane] = child;
    }

    /// The slots of the leaf `child`.
    #[inline(always)]
    fn slots(child: u32) -> Range<usize> {
        let first = ((child & !LEAF) >> 2) as usize * LEAF_SLOTS;
        first..first + (child & 3) as usize + 1
    }

    /// Closest hit: `leaf(slots, t_max)` tests the primitives in `slots` (one leaf, its
    /// first slot a multiple of [`LEAF_SLOTS`]) and returns the distance and slot of the
    /// nearest below `t_max`. Returns the distance and slot of the nearest overall.
    /// Children are visited nearest box first.
    #[inline]
    pub fn closest(
        &self,
        ray: &Ray,
        t_max: f32,
        leaf: impl FnMut(Range<usize>, f32) -> Option<(f32, usize)>,
    ) -> Option<(f32, usize)> {
        if self.stack_bound <= IN_PLACE {
            self.closest_with(InPlace::new(), ray, t_max, leaf)
        } else {
            self.closest_with(Vec::with_capacity(self.stack_bound), ray, t_max, leaf)
        }
    }

    /// [`Bvh::closest`] with the stack `stack` (empty, with room for
    /// [`Bvh::stack_bound`] entries): each entry a node to visit and the distance at which
    /// the ray enters its box.
    #[inline(always)]
    fn closest_with(
        &self,
        mut stack: impl Stack<(u32, f32)>,
        ray: &Ray,
        t_max: f32,
        mut leaf: impl FnMut(Range<usize>, f32) -> Option<(f32, usize)>,
    ) -> Option<(f32, usize)> {
        let r = BoxRay::new(ray);
        let mut best = t_max;
        let mut found = None;
        let mut node = 0u32;
        'traversal: loop {
            if node & LEAF != 0 {
                if let Some((t, slot)) = leaf(Self::slots(node), best) {
                    best = t;
                    found = Some((t, slot));
                }
            } else {
                let n = &self.nodes[node as usize];
                let (near, hit) = r.enter(n, best);
                let mut mask = hit.bitmask();
                if mask != 0 {
                    let near = near.to_array();
                    // The hit children, nearest first: the nearest is visited next, the
                    // others pushed farthest first so they pop nearest first.
                    let mut order = [(0f32, 0u32); 4];
                    let mut count = 0;
                    while mask != 0 {
                        let lane = mask.trailing_zeros() as usize;
                        mask &= mask - 1;
                        let mut i = count;
                        while i > 0 && order[i - 1].0 < near[lane] {
                            order[i] = order[i - 1];
                            i -= 1;
                        }
                        order[i] = (near[lane], n.child[lane]);
                        count += 1;
                    }
                    for &(t, child) in &order[..count - 1] {
                        stack.push((child, t));
                    }
                    node = order[count - 1].1;
                    continue 'traversal;
                }
            }
            loop {
                let Some((next, t_near)) = stack.pop() else {
                    return found;
                };
                if t_near <= best * 1.000_000_4 {
                    node = next;
                    continue 'traversal;
                }
            }
        }
    }

    /// Any hit below `t_max`: `leaf(slots, t_max)` says whether a primitive in `slots`
    /// lies along the ray before `t_max`; traversal stops at the first that does.
    #[inline]
    pub fn any(&self, ray: &Ray, t_max: f32, leaf: impl FnMut(Range<usize>, f32) -> bool) -> bool {
        if self.stack_bound <= IN_PLACE {
            self.any_with(InPlace::new(), ray, t_max, leaf)
        } else {
            self.any_with(Vec::with_capacity(self.stack_bound), ray, t_max, leaf)
        }
    }

    /// [`Bvh::any`] with the stack `stack` (empty, with room for [`Bvh::stack_bound`]
    /// entries) of nodes to visit.
    #[inline(always)]
    fn any_with(
        &self,
        mut stack: impl Stack<u32>,
        ray: &Ray,
        t_max: f32,
        mut leaf: impl FnMut(Range<usize>, f32) -> bool,
    ) -> bool {
        let r = BoxRay::new(ray);
        let mut node = 0u32;
        loop {
            if node & LEAF != 0 {
                if leaf(Self::slots(node), t_max) {
                    return true;
                }
            } else {
                let n = &self.nodes[node as usize];
                let mut mask = r.enter(n, t_max).1.bitmask();
                while mask != 0 {
                    let lane = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    stack.push(n.child[lane]);
                }
            }
            let Some(next) = stack.pop() else {
                return false;
            };
            node = next;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::{Sampler, uniform_sphere};
    use glam::{Vec3, Vec3A};

    /// Where `ray` enters `b` in `(0, t_max)`, if it does from outside: the primitive of
    /// these tests, a solid box seen from outside.
    fn enter(b: &Aabb, ray: &Ray, t_max: f32) -> Option<f32> {
        let o = Vec3A::from(ray.origin);
        let inv = Vec3A::ONE / Vec3A::from(ray.dir);
        let (t0, t1) = ((b.min - o) * inv, (b.max - o) * inv);
        let (near, far) = (t0.min(t1).max_element(), t0.max(t1).min_element());
        (near > 0.0 && near <= far && near < t_max).then_some(near)
    }

    /// A heap stack that remembers how many entries it held at most.
    struct Recording<'a, T> {
        items: Vec<T>,
        most: &'a mut usize,
    }

    impl<'a, T> Recording<'a, T> {
        fn new(most: &'a mut usize) -> Self {
            Self {
                items: Vec::new(),
                most,
            }
        }
    }

    impl<T> Stack<T> for Recording<'_, T> {
        fn push(&mut self, item: T) {
            self.items.push(item);
            *self.most = (*self.most).max(self.items.len());
        }

        fn pop(&mut self) -> Option<T> {
            self.items.pop()
        }
    }

    /// Casts random rays at a BVH over `boxes` and checks its closest and any hits
    /// against testing every box, and that no traversal's stack outgrew the tree's bound.
    /// Returns that bound and the most entries a stack held.
    fn agrees_with_testing_every_box(boxes: &[Aabb], sampler: &mut Sampler) -> (usize, usize) {
        let bvh = Bvh::build(boxes);
        let by_slot = bvh.by_slot(boxes, Aabb::empty());
        let mut most = 0;
        for i in 0..3000 {
            // Every fourth ray from the centre, inside every nested box below: it hits none
            // of them (they are solid only from outside), so it visits the whole tree.
            let o = Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
            let o = if i % 4 == 0 {
                Vec3::ZERO
            } else {
                2.0 * o - 1.0
            };
            let ray = Ray::new(o, uniform_sphere(sampler.next_2d()));
            let t_max = if i % 3 == 0 { 0.3 } else { f32::INFINITY };
            let brute = boxes
                .iter()
                .filter_map(|b| enter(b, &ray, t_max))
                .min_by(f32::total_cmp);
            // Both leaf tests borrow only, so they are `Copy`: each traversal gets its own.
            let nearest = |slots: Range<usize>, t_max| {
                slots
                    .filter_map(|s| Some((enter(&by_slot[s], &ray, t_max)?, s)))
                    .min_by(|a, b| a.0.total_cmp(&b.0))
            };
            let any_of = |mut slots: Range<usize>, t_max| {
                slots.any(|s| enter(&by_slot[s], &ray, t_max).is_some())
            };
            let closest = bvh.closest(&ray, t_max, nearest);
            assert_eq!(closest.map(|c| c.0), brute, "ray {i}: {ray:?}");
            let any = bvh.any(&ray, t_max, any_of);
            assert_eq!(any, brute.is_some(), "ray {i}: {ray:?}");
            let recorded = bvh.closest_with(Recording::new(&mut most), &ray, t_max, nearest);
            assert_eq!(recorded, closest);
            assert_eq!(
                bvh.any_with(Recording::new(&mut most), &ray, t_max, any_of),
                any
            );
        }
        assert!(most <= bvh.stack_bound, "{most} > {}", bvh.stack_bound);
        (bvh.stack_bound, most)
    }

    #[test]
    fn shallow_and_deep_trees_find_what_testing_every_box_finds() {
        let mut sampler = Sampler::new(5, 6);
        let scattered: Vec<Aabb> = (0..2000)
            .map(|_| {
                let c = Vec3A::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
                Aabb::new(2.0 * c - 1.0, 2.0 * c - 1.0 + 0.05 * sampler.next_1d())
            })
            .collect();
        let (bound, _) = agrees_with_testing_every_box(&scattered, &mut sampler);
        assert!(
            bound <= IN_PLACE,
            "{bound}: the in-place stack is what this tests"
        );
        // Boxes nested like Russian dolls, each 0.9 times the one around it. A ray from
        // the centre enters every node's children (and hits no box), so it visits the
        // whole tree. Four such boxes are four leaves under the root, all of which `any`
        // pushes at once: the bound is reached, not loose.
        let nested = |n: i32| -> Vec<Aabb> {
            (0..n)
                .map(|i| Aabb::new(Vec3A::splat(-0.9f32.powi(i)), Vec3A::splat(0.9f32.powi(i))))
                .collect()
        };
        let (bound, most) = agrees_with_testing_every_box(&nested(4), &mut sampler);
        assert_eq!((bound, most), (4, 4));
        // Three hundred: the build merges the two smallest at a time, so the tree is a
        // chain, and a ray from the centre leaves children waiting at each of its levels,
        // more than the in-place stack holds.
        let (bound, most) = agrees_with_testing_every_box(&nested(300), &mut sampler);
        assert!(bound > IN_PLACE && most > IN_PLACE, "{bound}, {most}");
    }
}
