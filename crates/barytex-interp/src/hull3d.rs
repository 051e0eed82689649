//! 3D convex hull with exact orientation.
//!
//! Quickhull (Barber, Dobkin & Huhdanpaa 1996) where every visibility decision is the exact sign
//! of [`orient3d`](crate::orient3d): a point joins a facet's conflict list only when it is
//! *strictly* outside the facet's plane, and a facet is removed only when the new point is
//! strictly outside it. With exact signs this builds a closed, consistently oriented, convex
//! triangulated surface whatever the input; the one thing strictness leaves behind is a vertex
//! that ended up flat (inside a face or an edge of the final hull, because a later point was
//! coplanar with it). Those are detected exactly (a strict corner has at least three distinct
//! facet planes around it) and, when there are any, the hull is rebuilt from the strict corners
//! alone, which are in convex position and cannot produce a flat vertex again.

use alloc::vec;
use alloc::vec::Vec;
use core::cmp::Ordering;
use core::fmt;

use glam::{Vec2, Vec3};

use crate::orient::orient2d_value;
use crate::orient3d::orient3d_sign_det;
use crate::{Orientation, orient2d};

/// The convex hull of a set of 3D points, by dimension: the corners are indices into the input.
///
/// The hull's vertices are exactly its *strict* corners: a point lying inside a face or on an
/// edge of the hull, or repeating another point, is never a vertex. Of equal points, the one with
/// the lowest index represents them all.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ConvexHull3d {
    /// No input points.
    Empty,
    /// All points are equal; `index` is 0.
    Point {
        /// The first point.
        index: usize,
    },
    /// All points are collinear (and not all equal): the two extremes, lexicographically
    /// smallest `(x, y, z)` first.
    Segment {
        /// `[lowest, highest]` in lexicographic `(x, y, z)` order.
        ends: [usize; 2],
    },
    /// All points are coplanar (and not collinear): the convex polygon in their plane.
    Polygon {
        /// The strict corners, counter-clockwise seen from the `+dropped_axis` side of the plane
        /// (that is, counter-clockwise in the coordinates `(dropped_axis + 1, dropped_axis + 2)`
        /// mod 3), starting from the lowest index.
        vertices: Vec<usize>,
        /// The axis (0 = x, 1 = y, 2 = z) dropped to project the plane injectively: the plane's
        /// normal has an exactly non-zero component along it.
        dropped_axis: usize,
    },
    /// A solid polytope.
    Polytope {
        /// The strict corners, sorted ascending.
        vertices: Vec<usize>,
        /// Triangles, counter-clockwise seen from outside (so `orient3d(a, b, c, p)` is never
        /// positive for an input point `p`); each starts with its lowest index and the list is
        /// sorted. Faces with more than three corners appear as several coplanar triangles.
        facets: Vec<[usize; 3]>,
    },
}

/// Why [`convex_hull_3d`] cannot answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum HullError3d {
    /// The point at `index` has a NaN or infinite coordinate (the first such point).
    NonFinite {
        /// Its position in the input.
        index: usize,
    },
    /// More than `u32::MAX` points (indices are stored as `u32` internally).
    TooManyPoints {
        /// The input length.
        len: usize,
    },
}

impl fmt::Display for HullError3d {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite { index } => {
                write!(f, "point {index} has a NaN or infinite coordinate")
            }
            Self::TooManyPoints { len } => {
                write!(f, "{len} points: at most u32::MAX are supported")
            }
        }
    }
}

impl core::error::Error for HullError3d {}

/// A property that a [`ConvexHull3d`] fails for its input, found by [`ConvexHull3d::validate`].
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum HullDefect3d {
    /// An index is not an index of the input (or the input holds a non-finite point).
    BadIndex {
        /// The offending index.
        index: usize,
    },
    /// The hull's kind does not fit the input (for example `Point` for unequal points, `Empty`
    /// for a non-empty input, or a polytope of fewer than four corners).
    WrongKind {
        /// A point the kind does not cover.
        point: usize,
    },
    /// An input point is strictly outside a facet (or off the polygon's plane, or outside a
    /// polygon edge, or off the segment).
    PointOutside {
        /// The point.
        point: usize,
        /// The facet (for a polygon `[a, b, b]` names the edge `a → b`).
        facet: [usize; 3],
    },
    /// A facet (or three consecutive polygon corners) has exactly collinear corners or turns the
    /// wrong way.
    DegenerateFacet {
        /// The facet.
        facet: [usize; 3],
    },
    /// A directed edge is used twice, or its reverse by no facet.
    EdgeNotShared {
        /// `[from, to]`.
        edge: [usize; 2],
    },
    /// The two facets at an edge bend inwards.
    ReflexEdge {
        /// `[from, to]`.
        edge: [usize; 2],
    },
    /// `V − E + F ≠ 2`.
    Euler {
        /// Distinct facet corners.
        vertices: usize,
        /// Undirected edges.
        edges: usize,
        /// Facets.
        facets: usize,
    },
    /// The vertex list is not the sorted set of the facets' corners.
    VertexListMismatch,
    /// A vertex is not a strict corner (it lies inside a face or an edge of the hull).
    NotStrictCorner {
        /// The vertex.
        vertex: usize,
    },
}

impl fmt::Display for HullDefect3d {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadIndex { index } => write!(f, "index {index} is not a finite input point"),
            Self::WrongKind { point } => {
                write!(f, "the hull's kind does not cover point {point}")
            }
            Self::PointOutside { point, facet } => {
                write!(f, "point {point} is outside facet {facet:?}")
            }
            Self::DegenerateFacet { facet } => write!(f, "facet {facet:?} is degenerate"),
            Self::EdgeNotShared { edge } => {
                write!(f, "edge {edge:?} is not shared by exactly two facets")
            }
            Self::ReflexEdge { edge } => write!(f, "edge {edge:?} is reflex"),
            Self::Euler {
                vertices,
                edges,
                facets,
            } => write!(f, "V − E + F = {vertices} − {edges} + {facets} ≠ 2"),
            Self::VertexListMismatch => {
                f.write_str("the vertex list is not the sorted set of facet corners")
            }
            Self::NotStrictCorner { vertex } => {
                write!(f, "vertex {vertex} is not a strict corner")
            }
        }
    }
}

impl core::error::Error for HullDefect3d {}

/// The convex hull of `points`, exact: every visibility and coplanarity decision is an exact
/// orientation sign, so the result is the true hull of the f32 input, with no tolerance.
///
/// Degenerate inputs are answered by dimension ([`ConvexHull3d::Empty`], `Point`, `Segment`,
/// `Polygon`); duplicates and points inside faces or on edges never become vertices. The output
/// is deterministic: the same input gives the same hull, and the vertex *set* (as points) does
/// not depend on the input order. `O(n log n)` expected for points in general position.
///
/// # Errors
/// [`HullError3d::NonFinite`] naming the first point with a NaN or infinite coordinate;
/// [`HullError3d::TooManyPoints`] beyond `u32::MAX` points.
///
/// ```
/// use barytex_interp::{convex_hull_3d, ConvexHull3d};
/// use glam::Vec3;
///
/// // A unit cube's corners, its centre, a face centre and a duplicate corner.
/// let mut points: Vec<Vec3> = (0..8)
///     .map(|i| Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, (i >> 2) as f32))
///     .collect();
/// points.extend([Vec3::splat(0.5), Vec3::new(0.5, 0.5, 1.0), Vec3::ONE]);
/// let hull = convex_hull_3d(&points)?;
/// assert_eq!(hull.vertices(), &[0, 1, 2, 3, 4, 5, 6, 7]);
/// assert_eq!(hull.facets().len(), 12); // six square faces, two triangles each
/// assert!(hull.validate(&points).is_ok());
///
/// let flat = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(0.2, 0.2, 0.0)];
/// assert!(matches!(convex_hull_3d(&flat)?, ConvexHull3d::Polygon { .. }));
/// # Ok::<(), barytex_interp::HullError3d>(())
/// ```
pub fn convex_hull_3d(points: &[Vec3]) -> Result<ConvexHull3d, HullError3d> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(HullError3d::NonFinite { index });
    }
    if u32::try_from(points.len()).is_err() {
        return Err(HullError3d::TooManyPoints { len: points.len() });
    }
    let all: Vec<u32> = (0..points.len() as u32).collect();
    Ok(hull_of_subset(points, &all))
}

/// The hull of `points[i]` for `i` in `subset` (ascending), indices into `points`.
fn hull_of_subset(points: &[Vec3], subset: &[u32]) -> ConvexHull3d {
    let pt = |i: u32| points[i as usize];
    let Some(&first) = subset.first() else {
        return ConvexHull3d::Empty;
    };
    // Lexicographic extremes, the first (lowest index) on ties.
    let (mut lo, mut hi) = (first, first);
    for &i in subset {
        if lex(pt(i), pt(lo)) == Ordering::Less {
            lo = i;
        }
        if lex(pt(i), pt(hi)) == Ordering::Greater {
            hi = i;
        }
    }
    if pt(lo) == pt(hi) {
        return ConvexHull3d::Point {
            index: first as usize,
        };
    }
    let (a, b) = (pt(lo), pt(hi));
    // Third corner: the point farthest from the line (approximately), confirmed exactly.
    let dir = b.as_dvec3() - a.as_dvec3();
    let far_from_line = |i: u32| dir.cross(pt(i).as_dvec3() - a.as_dvec3()).length_squared();
    let Some(c) = pick(subset, far_from_line, |i| !collinear(a, b, pt(i))) else {
        return ConvexHull3d::Segment {
            ends: [lo as usize, hi as usize],
        };
    };
    let c_pt = pt(c);
    // Fourth corner: the largest |det| (exact sign, so a non-zero one is truly off the plane).
    let height = |i: u32| orient3d_sign_det(a, b, c_pt, pt(i));
    let mut d = None;
    let mut best = 0.0;
    for &i in subset {
        let h = height(i).abs();
        if h > best {
            best = h;
            d = Some(i);
        }
    }
    let Some(d) = d else {
        return planar_hull(points, subset, [a, b, c_pt]);
    };
    let mut builder = Quickhull::new(points, subset.len());
    builder.run(subset, [lo, hi, c, d]);
    let (vertices, facets) = builder.finish();
    let strict = strict_corners(points, &vertices, &facets);
    if strict.len() < vertices.len() {
        // Some corners are flat: the strict ones are in convex position, so their hull has
        // exactly them as corners (and contains every other point).
        return hull_of_subset(points, &strict);
    }
    canonical_polytope(vertices, facets)
}

/// `points[i]`'s order by `(x, y, z)`, `-0.0 == 0.0`.
fn lex(p: Vec3, q: Vec3) -> Ordering {
    let by = |a: f32, b: f32| a.partial_cmp(&b).unwrap_or(Ordering::Equal);
    by(p.x, q.x).then(by(p.y, q.y)).then(by(p.z, q.z))
}

/// The projections dropping x, y and z: `(y, z)`, `(z, x)`, `(x, y)`. Counter-clockwise in
/// projection `k` is counter-clockwise seen from the `+k` side.
fn project(p: Vec3, axis: usize) -> Vec2 {
    match axis {
        0 => Vec2::new(p.y, p.z),
        1 => Vec2::new(p.z, p.x),
        _ => Vec2::new(p.x, p.y),
    }
}

/// Exactly collinear: `(b − a) × (p − a) = 0`, whose components are the three projections'
/// 2D orientations.
fn collinear(a: Vec3, b: Vec3, p: Vec3) -> bool {
    (0..3).all(|k| {
        orient2d(project(a, k), project(b, k), project(p, k)) == Ok(Orientation::Collinear)
    })
}

/// The index maximising the approximate `score` that passes the exact `accept`; if the best
/// score fails it (rounding), the first index that passes.
fn pick(subset: &[u32], score: impl Fn(u32) -> f64, accept: impl Fn(u32) -> bool) -> Option<u32> {
    let mut best = None;
    let mut best_score = 0.0;
    for &i in subset {
        let s = score(i);
        if s > best_score {
            best_score = s;
            best = Some(i);
        }
    }
    match best {
        Some(i) if accept(i) => Some(i),
        _ => subset.iter().copied().find(|&i| accept(i)),
    }
}

/// The hull of coplanar points: Andrew's monotone chain in the projection dropping the axis along
/// which the plane's normal is largest (exactly non-zero), with exact 2D orientations.
fn planar_hull(points: &[Vec3], subset: &[u32], [a, b, c]: [Vec3; 3]) -> ConvexHull3d {
    let mut dropped_axis = 2;
    let mut best = 0.0;
    for k in 0..3 {
        // The normal's component k is the orientation of projection k (exactly non-zero for at
        // least one k, as a, b, c are not collinear).
        let n = orient2d_value(project(a, k), project(b, k), project(c, k)).unwrap_or(0.0);
        if n.abs() > best {
            best = n.abs();
            dropped_axis = k;
        }
    }
    let proj = |i: u32| project(points[i as usize], dropped_axis);
    let mut sorted: Vec<u32> = subset.to_vec();
    sorted.sort_by(|&i, &j| {
        let (p, q) = (proj(i), proj(j));
        let by = |a: f32, b: f32| a.partial_cmp(&b).unwrap_or(Ordering::Equal);
        by(p.x, q.x).then(by(p.y, q.y)).then(i.cmp(&j))
    });
    // The projection is injective on the plane: equal projections are equal points.
    sorted.dedup_by(|later, earlier| proj(*later) == proj(*earlier));
    let left_turn = |h: &[u32], p: u32| {
        let n = h.len();
        orient2d(proj(h[n - 2]), proj(h[n - 1]), proj(p)) == Ok(Orientation::CounterClockwise)
    };
    let mut hull: Vec<u32> = Vec::with_capacity(sorted.len() + 1);
    for &p in &sorted {
        while hull.len() >= 2 && !left_turn(&hull, p) {
            hull.pop();
        }
        hull.push(p);
    }
    let lower = hull.len() + 1;
    for &p in sorted.iter().rev().skip(1) {
        while hull.len() >= lower && !left_turn(&hull, p) {
            hull.pop();
        }
        hull.push(p);
    }
    hull.pop(); // the first point again
    let start = hull
        .iter()
        .enumerate()
        .min_by_key(|&(_, &v)| v)
        .map_or(0, |(k, _)| k);
    hull.rotate_left(start);
    ConvexHull3d::Polygon {
        vertices: hull.into_iter().map(|v| v as usize).collect(),
        dropped_axis,
    }
}

/// A facet index that marks "none".
const NONE: u32 = u32::MAX;

/// A triangle of the growing hull, counter-clockwise seen from outside.
struct Facet {
    /// Corners.
    v: [u32; 3],
    /// `n[i]` is the facet across the edge `v[i] → v[i + 1]`.
    n: [u32; 3],
    alive: bool,
    /// The iteration that last tested this facet against its point, and the answer.
    stamp: u32,
    visible: bool,
    /// Input points strictly outside this facet (and assigned to it).
    outside: Vec<u32>,
    /// The outside point farthest from the plane (approximately; ties to the lowest index).
    far: u32,
    far_height: f64,
}

/// Quickhull's working state.
struct Quickhull<'a> {
    points: &'a [Vec3],
    facets: Vec<Facet>,
    /// Facets that may still have outside points, processed last-in first-out.
    pending: Vec<u32>,
    /// Per point: the new facet whose horizon edge starts there (scratch of one iteration).
    starts_at: Vec<u32>,
}

impl<'a> Quickhull<'a> {
    fn new(points: &'a [Vec3], subset_len: usize) -> Self {
        Self {
            points,
            facets: Vec::with_capacity(8 * subset_len.min(1 << 16) + 4),
            pending: Vec::new(),
            starts_at: vec![NONE; points.len()],
        }
    }

    fn pt(&self, i: u32) -> Vec3 {
        self.points[i as usize]
    }

    /// `det[b − a, c − a, p − a]` of facet `f` and point `p`: exact sign, positive outside.
    fn height(&self, f: u32, p: u32) -> f64 {
        let [a, b, c] = self.facets[f as usize].v;
        orient3d_sign_det(self.pt(a), self.pt(b), self.pt(c), self.pt(p))
    }

    fn add_facet(&mut self, v: [u32; 3]) -> u32 {
        let id = self.facets.len() as u32;
        self.facets.push(Facet {
            v,
            n: [NONE; 3],
            alive: true,
            stamp: 0,
            visible: false,
            outside: Vec::new(),
            far: NONE,
            far_height: 0.0,
        });
        id
    }

    /// Gives `p` to the first of `candidates` it is strictly outside of; `false` if none.
    fn assign(&mut self, p: u32, candidates: &[u32]) -> bool {
        for &f in candidates {
            let h = self.height(f, p);
            if h > 0.0 {
                let facet = &mut self.facets[f as usize];
                facet.outside.push(p);
                if h > facet.far_height || (h == facet.far_height && p < facet.far) {
                    facet.far_height = h;
                    facet.far = p;
                }
                return true;
            }
        }
        false
    }

    fn run(&mut self, subset: &[u32], [p0, p1, p2, p3]: [u32; 4]) {
        // Orient the tetrahedron so that (p0, p1, p2) faces away from p3.
        let (p1, p2) =
            if orient3d_sign_det(self.pt(p0), self.pt(p1), self.pt(p2), self.pt(p3)) > 0.0 {
                (p2, p1)
            } else {
                (p1, p2)
            };
        let tets = [[p0, p1, p2], [p0, p3, p1], [p1, p3, p2], [p0, p2, p3]];
        let ids: Vec<u32> = tets.iter().map(|&v| self.add_facet(v)).collect();
        for &f in &ids {
            for i in 0..3 {
                let v = self.facets[f as usize].v;
                let (from, to) = (v[i], v[(i + 1) % 3]);
                let g = ids
                    .iter()
                    .copied()
                    .find(|&g| g != f && has_edge(self.facets[g as usize].v, to, from));
                self.facets[f as usize].n[i] = g.unwrap_or(NONE);
            }
        }
        for &p in subset {
            if p != p0 && p != p1 && p != p2 && p != p3 {
                self.assign(p, &ids);
            }
        }
        self.pending.extend(ids.iter().rev());
        let mut iteration = 0u32;
        let mut visible = Vec::new();
        let mut horizon: Vec<(u32, u32, u32)> = Vec::new();
        let mut stack = Vec::new();
        let mut new_facets = Vec::new();
        while let Some(f) = self.pending.pop() {
            let facet = &self.facets[f as usize];
            if !facet.alive || facet.outside.is_empty() {
                continue;
            }
            let p = facet.far;
            iteration += 1;
            // The visible region: facets strictly below p, connected to f.
            visible.clear();
            horizon.clear();
            stack.push(f);
            self.facets[f as usize].stamp = iteration;
            self.facets[f as usize].visible = true;
            while let Some(g) = stack.pop() {
                visible.push(g);
                for i in 0..3 {
                    let h = self.facets[g as usize].n[i];
                    let seen = self.facets[h as usize].stamp == iteration;
                    if !seen {
                        let vis = self.height(h, p) > 0.0;
                        let hf = &mut self.facets[h as usize];
                        hf.stamp = iteration;
                        hf.visible = vis;
                        if vis {
                            stack.push(h);
                        }
                    }
                    if !self.facets[h as usize].visible {
                        let v = self.facets[g as usize].v;
                        horizon.push((v[i], v[(i + 1) % 3], h));
                    }
                }
            }
            // A cone of new facets from p over the horizon.
            new_facets.clear();
            for &(u, w, h) in &horizon {
                let nf = self.add_facet([u, w, p]);
                self.facets[nf as usize].n[0] = h;
                let hv = self.facets[h as usize].v;
                if let Some(j) = (0..3).find(|&j| hv[j] == w && hv[(j + 1) % 3] == u) {
                    self.facets[h as usize].n[j] = nf;
                }
                self.starts_at[u as usize] = nf;
                new_facets.push(nf);
            }
            for &nf in &new_facets {
                let w = self.facets[nf as usize].v[1];
                let next = self.starts_at[w as usize];
                self.facets[nf as usize].n[1] = next;
                if let Some(m) = self.facets.get_mut(next as usize) {
                    m.n[2] = nf;
                }
            }
            // The visible facets' outside points go to the new facets (a point outside the new
            // hull is outside one of them) or are inside and dropped.
            for &g in &visible {
                let facet = &mut self.facets[g as usize];
                facet.alive = false;
                let outside = core::mem::take(&mut facet.outside);
                for q in outside {
                    if q != p {
                        self.assign(q, &new_facets);
                    }
                }
            }
            for &nf in new_facets.iter().rev() {
                if !self.facets[nf as usize].outside.is_empty() {
                    self.pending.push(nf);
                }
            }
        }
    }

    /// The corners (sorted) and the live facets.
    fn finish(self) -> (Vec<u32>, Vec<[u32; 3]>) {
        let facets: Vec<[u32; 3]> = self
            .facets
            .iter()
            .filter(|f| f.alive)
            .map(|f| f.v)
            .collect();
        let mut vertices: Vec<u32> = facets.iter().flatten().copied().collect();
        vertices.sort_unstable();
        vertices.dedup();
        (vertices, facets)
    }
}

fn has_edge(v: [u32; 3], from: u32, to: u32) -> bool {
    (0..3).any(|i| v[i] == from && v[(i + 1) % 3] == to)
}

/// The strict corners among `vertices` (in their order) of the closed convex surface `facets`:
/// those whose incident facets lie in at least three distinct planes (in one plane a vertex is
/// inside a face, in two on an edge).
fn strict_corners(points: &[Vec3], vertices: &[u32], facets: &[[u32; 3]]) -> Vec<u32> {
    // Incident facets per point, in compressed rows.
    let mut start = vec![0u32; points.len() + 1];
    for &v in facets.iter().flatten() {
        start[v as usize + 1] += 1;
    }
    for i in 0..points.len() {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut incident = vec![0u32; 3 * facets.len()];
    for (f, corners) in facets.iter().enumerate() {
        for &v in corners {
            incident[fill[v as usize] as usize] = f as u32;
            fill[v as usize] += 1;
        }
    }
    let pt = |i: u32| points[i as usize];
    let coplanar = |plane: [u32; 3], f: [u32; 3]| {
        let [a, b, c] = plane.map(pt);
        f.iter()
            .all(|&x| plane.contains(&x) || orient3d_sign_det(a, b, c, pt(x)) == 0.0)
    };
    let is_strict = |v: u32| {
        let around = &incident[start[v as usize] as usize..start[v as usize + 1] as usize];
        let mut planes: [Option<[u32; 3]>; 2] = [None, None];
        for &f in around {
            let f = facets[f as usize];
            match planes {
                [None, _] => planes[0] = Some(f),
                [Some(p), None] => {
                    if !coplanar(p, f) {
                        planes[1] = Some(f);
                    }
                }
                [Some(p), Some(q)] => {
                    if !coplanar(p, f) && !coplanar(q, f) {
                        return true;
                    }
                }
            }
        }
        false
    };
    vertices.iter().copied().filter(|&v| is_strict(v)).collect()
}

/// Facets rotated to start at their lowest index and sorted; vertices already sorted.
fn canonical_polytope(vertices: Vec<u32>, facets: Vec<[u32; 3]>) -> ConvexHull3d {
    let mut facets: Vec<[usize; 3]> = facets
        .into_iter()
        .map(|[a, b, c]| {
            let f = [a as usize, b as usize, c as usize];
            if a <= b && a <= c {
                f
            } else if b <= c {
                [f[1], f[2], f[0]]
            } else {
                [f[2], f[0], f[1]]
            }
        })
        .collect();
    facets.sort_unstable();
    ConvexHull3d::Polytope {
        vertices: vertices.into_iter().map(|v| v as usize).collect(),
        facets,
    }
}

impl ConvexHull3d {
    /// The hull's corners as input indices: empty, one, the two ends, the polygon in order, or
    /// the polytope's sorted corners.
    #[must_use]
    pub fn vertices(&self) -> &[usize] {
        match self {
            Self::Empty => &[],
            Self::Point { index } => core::slice::from_ref(index),
            Self::Segment { ends } => ends,
            Self::Polygon { vertices, .. } | Self::Polytope { vertices, .. } => vertices,
        }
    }

    /// The polytope's triangles (counter-clockwise seen from outside); empty for the lower
    /// dimensional kinds.
    #[must_use]
    pub fn facets(&self) -> &[[usize; 3]] {
        match self {
            Self::Polytope { facets, .. } => facets,
            _ => &[],
        }
    }

    /// Checks that this is the convex hull of `points`, exactly: every input point on the inner
    /// side of (or on) every facet, every facet non-degenerate, every directed edge matched by
    /// exactly one reverse edge, every edge convex, `V − E + F = 2`, the vertex list the sorted set
    /// of facet corners, and every vertex a strict corner; the lower-dimensional kinds get the
    /// analogous checks (all points equal, collinear within the segment, coplanar within a
    /// strictly convex counter-clockwise polygon).
    ///
    /// Meant for tests and fuzzing: `O(n · F)` orientation tests.
    ///
    /// # Errors
    /// The first [`HullDefect3d`] found.
    pub fn validate(&self, points: &[Vec3]) -> Result<(), HullDefect3d> {
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(HullDefect3d::BadIndex { index });
        }
        for &index in self.vertices().iter().chain(self.facets().iter().flatten()) {
            if index >= points.len() {
                return Err(HullDefect3d::BadIndex { index });
            }
        }
        match self {
            Self::Empty => match points.len() {
                0 => Ok(()),
                _ => Err(HullDefect3d::WrongKind { point: 0 }),
            },
            Self::Point { index } => match points.iter().position(|&p| p != points[*index]) {
                None => Ok(()),
                Some(point) => Err(HullDefect3d::WrongKind { point }),
            },
            Self::Segment { ends: [lo, hi] } => validate_segment(points, *lo, *hi),
            Self::Polygon {
                vertices,
                dropped_axis,
            } => validate_polygon(points, vertices, *dropped_axis),
            Self::Polytope { vertices, facets } => validate_polytope(points, vertices, facets),
        }
    }
}

fn validate_segment(points: &[Vec3], lo: usize, hi: usize) -> Result<(), HullDefect3d> {
    let (a, b) = (points[lo], points[hi]);
    if lex(a, b) != Ordering::Less {
        return Err(HullDefect3d::WrongKind { point: hi });
    }
    for (i, &p) in points.iter().enumerate() {
        // Along a line, lexicographic order is the order along it.
        if !collinear(a, b, p) || lex(p, a) == Ordering::Less || lex(p, b) == Ordering::Greater {
            return Err(HullDefect3d::PointOutside {
                point: i,
                facet: [lo, hi, hi],
            });
        }
    }
    Ok(())
}

fn validate_polygon(points: &[Vec3], vertices: &[usize], axis: usize) -> Result<(), HullDefect3d> {
    let n = vertices.len();
    if n < 3 || axis > 2 {
        return Err(HullDefect3d::WrongKind { point: 0 });
    }
    let proj = |i: usize| project(points[i], axis);
    let ccw = |a: usize, b: usize, c: usize| orient2d(proj(a), proj(b), proj(c));
    for k in 0..n {
        let (a, b, c) = (vertices[k], vertices[(k + 1) % n], vertices[(k + 2) % n]);
        // Strictly convex turns, and a fan from the first corner that turns the same way (so the
        // polygon winds once).
        let fan = k + 2 >= n || ccw(vertices[0], b, c) == Ok(Orientation::CounterClockwise);
        if ccw(a, b, c) != Ok(Orientation::CounterClockwise) || !fan {
            return Err(HullDefect3d::DegenerateFacet { facet: [a, b, c] });
        }
    }
    let [a, b, c] = [0, 1, 2].map(|k| points[vertices[k]]);
    for (i, &p) in points.iter().enumerate() {
        if orient3d_sign_det(a, b, c, p) != 0.0 {
            return Err(HullDefect3d::PointOutside {
                point: i,
                facet: [vertices[0], vertices[1], vertices[2]],
            });
        }
        for k in 0..n {
            let (u, w) = (vertices[k], vertices[(k + 1) % n]);
            if ccw(u, w, i) == Ok(Orientation::Clockwise) {
                return Err(HullDefect3d::PointOutside {
                    point: i,
                    facet: [u, w, w],
                });
            }
        }
    }
    Ok(())
}

fn validate_polytope(
    points: &[Vec3],
    vertices: &[usize],
    facets: &[[usize; 3]],
) -> Result<(), HullDefect3d> {
    let mut corners: Vec<usize> = facets.iter().flatten().copied().collect();
    corners.sort_unstable();
    corners.dedup();
    if corners.len() < 4 {
        return Err(HullDefect3d::WrongKind { point: 0 });
    }
    if corners != vertices {
        return Err(HullDefect3d::VertexListMismatch);
    }
    for &f in facets {
        let [a, b, c] = f.map(|i| points[i]);
        if collinear(a, b, c) {
            return Err(HullDefect3d::DegenerateFacet { facet: f });
        }
    }
    // Directed edges, sorted, each with the facet's third corner.
    let mut edges: Vec<([usize; 2], usize)> = facets
        .iter()
        .flat_map(|&[a, b, c]| [([a, b], c), ([b, c], a), ([c, a], b)])
        .collect();
    edges.sort_unstable();
    for pair in edges.windows(2) {
        if pair[0].0 == pair[1].0 {
            return Err(HullDefect3d::EdgeNotShared { edge: pair[0].0 });
        }
    }
    for &([u, w], x) in &edges {
        let Ok(k) = edges.binary_search_by(|e| e.0.cmp(&[w, u])) else {
            return Err(HullDefect3d::EdgeNotShared { edge: [u, w] });
        };
        let y = edges[k].1;
        if orient3d_sign_det(points[u], points[w], points[x], points[y]) > 0.0 {
            return Err(HullDefect3d::ReflexEdge { edge: [u, w] });
        }
    }
    let (v, e, f) = (corners.len(), edges.len() / 2, facets.len());
    if v + f != e + 2 {
        return Err(HullDefect3d::Euler {
            vertices: v,
            edges: e,
            facets: f,
        });
    }
    for &facet in facets {
        let [a, b, c] = facet.map(|i| points[i]);
        if let Some(point) = points
            .iter()
            .position(|&p| orient3d_sign_det(a, b, c, p) > 0.0)
        {
            return Err(HullDefect3d::PointOutside { point, facet });
        }
    }
    let facets32: Vec<[u32; 3]> = facets.iter().map(|f| f.map(|i| i as u32)).collect();
    let vertices32: Vec<u32> = vertices.iter().map(|&v| v as u32).collect();
    let strict = strict_corners(points, &vertices32, &facets32);
    match vertices32
        .iter()
        .zip(strict.iter().chain(core::iter::repeat(&u32::MAX)))
        .find(|(v, s)| v != s)
    {
        Some((&vertex, _)) => Err(HullDefect3d::NotStrictCorner {
            vertex: vertex as usize,
        }),
        None => Ok(()),
    }
}
