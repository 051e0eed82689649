//! Octree rendering (Doctor and Torborg 1981; the Finnish lecture notes *Octreen piirtäminen*
//! and *Octree edestä taakse*, pp. 273–274). An octree of coloured voxels can be drawn
//!
//! - **back to front without any depth comparison**: at every node the child farthest from the
//!   eye first, then its three neighbours, then the next three, the nearest last — a valid
//!   painter's order because two children can only occlude each other across the planes that
//!   separate them, and the child on the eye's side of every such plane comes later
//!   ([`Octree::back_to_front`], [`render_back_to_front`]);
//! - **front to back** in the reverse order, with a screen-space region quadtree
//!   ([`CoverageQuadtree`]) that records which pixels are covered: a node whose projection is
//!   fully covered is skipped with its whole subtree ([`render_front_to_back`]).

use barytex_raster::{CullMode, DepthCompare, Fragment, Framebuffer, PipelineState, Shader, draw};
use glam::{UVec3, Vec3, Vec4};

use crate::Camera;

/// One node of an [`Octree`].
#[derive(Clone, Debug, PartialEq)]
enum Node {
    Empty,
    Leaf(Vec3),
    Branch(Box<[Node; 8]>),
}

/// A filled cube of the octree: its minimum corner, side and colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Voxel {
    /// The corner with the smallest coordinates.
    pub min: Vec3,
    /// Side length.
    pub size: f32,
    /// Linear-light colour.
    pub colour: Vec3,
}

/// A cube `[origin, origin + size]³` split into `2^depth` cells per side, each empty or coloured.
/// Child `k` of a node is the octant whose `x`, `y`, `z` halves are bits 0, 1, 2 of `k` (1: the
/// upper half). Uniform subtrees are not merged (a leaf is one cell), empty ones are.
#[derive(Clone, Debug, PartialEq)]
pub struct Octree {
    root: Node,
    origin: Vec3,
    size: f32,
    depth: u32,
}

/// The order in which the children of a node are drawn back to front, for the eye in octant
/// `near` of the node (bit `i` set: the eye is on the upper side of the node's `i`-axis plane):
/// the farthest child `near ^ 7`, then those one plane nearer, two planes nearer, and `near`.
///
/// ```
/// use barytex_shade::child_order;
/// // Eye on the +x, +y, +z side: (0, 0, 0) first, (1, 1, 1) last.
/// assert_eq!(child_order(7), [0, 1, 2, 4, 3, 5, 6, 7]);
/// ```
#[must_use]
pub fn child_order(near: usize) -> [usize; 8] {
    let far = (near ^ 7) & 7;
    [0, 1, 2, 4, 3, 5, 6, 7].map(|flip| far ^ flip)
}

impl Octree {
    /// Builds the octree of `2^depth` cells per side over `[origin, origin + size]³` from
    /// `cell(i, j, k)` (`None`: empty). `depth` is clamped to `0..=8`.
    ///
    /// ```
    /// use barytex_shade::Octree;
    /// use glam::{UVec3, Vec3};
    ///
    /// // A 4³ grid with the lower half filled.
    /// let tree = Octree::from_cells(2, Vec3::ZERO, 1.0, |c: UVec3| (c.y < 2).then_some(Vec3::ONE));
    /// assert_eq!(tree.back_to_front(Vec3::splat(5.0)).len(), 32);
    /// ```
    #[must_use]
    pub fn from_cells(
        depth: u32,
        origin: Vec3,
        size: f32,
        cell: impl Fn(UVec3) -> Option<Vec3>,
    ) -> Self {
        let depth = depth.min(8);
        fn build(level: u32, at: UVec3, cell: &dyn Fn(UVec3) -> Option<Vec3>) -> Node {
            if level == 0 {
                return cell(at).map_or(Node::Empty, Node::Leaf);
            }
            let half = 1 << (level - 1);
            let children: [Node; 8] = core::array::from_fn(|k| {
                let offset = UVec3::new(k as u32 & 1, (k as u32 >> 1) & 1, (k as u32 >> 2) & 1);
                build(level - 1, at + offset * half, cell)
            });
            if children.iter().all(|c| *c == Node::Empty) {
                Node::Empty
            } else {
                Node::Branch(Box::new(children))
            }
        }
        Self {
            root: build(depth, UVec3::ZERO, &cell),
            origin,
            size,
            depth,
        }
    }

    /// The filled cells in back-to-front order as seen from `eye` (a valid painter's order for
    /// any eye position outside the filled cells).
    #[must_use]
    pub fn back_to_front(&self, eye: Vec3) -> Vec<Voxel> {
        let mut out = Vec::new();
        self.walk(
            &self.root,
            self.origin,
            self.size,
            eye,
            false,
            &mut |v, leaf| {
                if leaf {
                    out.push(v);
                }
                true
            },
        );
        out
    }

    /// The filled cells in front-to-back order (the reverse of [`back_to_front`](Self::back_to_front)).
    #[must_use]
    pub fn front_to_back(&self, eye: Vec3) -> Vec<Voxel> {
        let mut v = self.back_to_front(eye);
        v.reverse();
        v
    }

    /// Cells per side.
    #[must_use]
    pub fn resolution(&self) -> u32 {
        1 << self.depth
    }

    /// Depth-first walk; `visit(cell, is_leaf)` returns whether to descend (for branches) —
    /// leaves and branches alike are offered as voxels of their bounds.
    fn walk(
        &self,
        node: &Node,
        min: Vec3,
        size: f32,
        eye: Vec3,
        front_first: bool,
        visit: &mut dyn FnMut(Voxel, bool) -> bool,
    ) {
        match node {
            Node::Empty => {}
            Node::Leaf(colour) => {
                visit(
                    Voxel {
                        min,
                        size,
                        colour: *colour,
                    },
                    true,
                );
            }
            Node::Branch(children) => {
                if !visit(
                    Voxel {
                        min,
                        size,
                        colour: Vec3::ZERO,
                    },
                    false,
                ) {
                    return;
                }
                let half = size / 2.0;
                let centre = min + Vec3::splat(half);
                let near = usize::from(eye.x > centre.x)
                    | usize::from(eye.y > centre.y) << 1
                    | usize::from(eye.z > centre.z) << 2;
                let mut order = child_order(near);
                if front_first {
                    order.reverse();
                }
                for k in order {
                    let offset =
                        Vec3::new((k & 1) as f32, ((k >> 1) & 1) as f32, ((k >> 2) & 1) as f32);
                    self.walk(
                        &children[k],
                        min + offset * half,
                        half,
                        eye,
                        front_first,
                        visit,
                    );
                }
            }
        }
    }
}

/// A vertex of a voxel face: position and the face's colour.
type FaceVertex = (Vec3, Vec3);

/// Draws voxel faces with flat colours; with `constant_depth`, every fragment gets depth ½, so
/// that the depth test `Less` lets only the first write through (a one-bit "covered" mask, no
/// depth comparison between voxels).
struct VoxelShader {
    view_projection: glam::Mat4,
    constant_depth: bool,
}

impl Shader for VoxelShader {
    type Vertex = FaceVertex;
    type Varying = Vec3;
    fn vertex(&self, &(p, c): &FaceVertex) -> (Vec4, Vec3) {
        let mut clip = self.view_projection * p.extend(1.0);
        if self.constant_depth {
            clip.z = 0.5 * clip.w;
        }
        (clip, c)
    }
    fn fragment(&self, f: &Fragment<'_, Vec3>) -> Option<Vec4> {
        Some(f.varying.extend(1.0))
    }
}

/// The six faces of a voxel as counter-clockwise (from outside) quads, each shaded by its
/// normal: `colour · (0.35 + 0.65·max(n·L, 0))` for the fixed light direction `L`.
fn voxel_faces(v: &Voxel, vertices: &mut Vec<FaceVertex>, indices: &mut Vec<u32>) {
    let light = Vec3::new(0.4, 0.8, 0.45).normalize();
    let c = |x: f32, y: f32, z: f32| v.min + Vec3::new(x, y, z) * v.size;
    let faces = [
        (
            Vec3::X,
            [c(1., 0., 0.), c(1., 1., 0.), c(1., 1., 1.), c(1., 0., 1.)],
        ),
        (
            -Vec3::X,
            [c(0., 0., 0.), c(0., 0., 1.), c(0., 1., 1.), c(0., 1., 0.)],
        ),
        (
            Vec3::Y,
            [c(0., 1., 0.), c(0., 1., 1.), c(1., 1., 1.), c(1., 1., 0.)],
        ),
        (
            -Vec3::Y,
            [c(0., 0., 0.), c(1., 0., 0.), c(1., 0., 1.), c(0., 0., 1.)],
        ),
        (
            Vec3::Z,
            [c(0., 0., 1.), c(1., 0., 1.), c(1., 1., 1.), c(0., 1., 1.)],
        ),
        (
            -Vec3::Z,
            [c(0., 0., 0.), c(0., 1., 0.), c(1., 1., 0.), c(1., 0., 0.)],
        ),
    ];
    for (n, quad) in faces {
        let colour = v.colour * (0.35 + 0.65 * n.dot(light).max(0.0));
        let base = vertices.len() as u32;
        vertices.extend(quad.map(|p| (p, colour)));
        indices.extend([base, base + 1, base + 2, base, base + 2, base + 3]);
    }
}

/// Draws the octree back to front into `target` with **no depth test** (painter's algorithm,
/// back faces culled); returns the number of voxels drawn.
pub fn render_back_to_front(tree: &Octree, camera: &Camera, target: &mut Framebuffer) -> usize {
    let voxels = tree.back_to_front(camera.eye);
    let (mut vertices, mut indices) = (Vec::new(), Vec::new());
    for v in &voxels {
        voxel_faces(v, &mut vertices, &mut indices);
    }
    let shader = VoxelShader {
        view_projection: camera.view_projection(),
        constant_depth: false,
    };
    let state = PipelineState {
        cull: CullMode::Back,
        depth_compare: None,
        depth_write: false,
        ..PipelineState::default()
    };
    draw(target, &shader, &state, &vertices, &indices);
    voxels.len()
}

/// Draws the voxels in any order with the ordinary depth test: the reference for the two
/// octree orders.
pub fn render_depth_tested(tree: &Octree, camera: &Camera, target: &mut Framebuffer) {
    let voxels = tree.back_to_front(camera.eye);
    let (mut vertices, mut indices) = (Vec::new(), Vec::new());
    // Front to back on purpose: painter's order would hide depth-test mistakes.
    for v in voxels.iter().rev() {
        voxel_faces(v, &mut vertices, &mut indices);
    }
    let shader = VoxelShader {
        view_projection: camera.view_projection(),
        constant_depth: false,
    };
    draw(
        target,
        &shader,
        &PipelineState::default(),
        &vertices,
        &indices,
    );
}

/// A region quadtree over the screen recording covered pixels: node `(level, x, y)` is covered
/// when all pixels of its `2^level`-pixel square are (pixels outside the image count as covered).
#[derive(Clone, Debug)]
pub struct CoverageQuadtree {
    /// `levels[l]` has `(side >> l)²` flags; `levels[0]` is per pixel.
    levels: Vec<Vec<bool>>,
    side: u32,
}

impl CoverageQuadtree {
    /// An empty quadtree for a `width × height` image.
    #[must_use]
    pub fn new(width: u32, height: u32) -> Self {
        let side = width.max(height).max(1).next_power_of_two();
        let mut levels = Vec::new();
        let mut s = side;
        loop {
            levels.push(vec![false; (s * s) as usize]);
            if s == 1 {
                break;
            }
            s /= 2;
        }
        let mut tree = Self { levels, side };
        for y in 0..side {
            for x in 0..side {
                if x >= width || y >= height {
                    tree.mark(x, y);
                }
            }
        }
        tree
    }

    /// Marks pixel `(x, y)` covered (ignored outside).
    pub fn mark(&mut self, x: u32, y: u32) {
        if x >= self.side || y >= self.side {
            return;
        }
        let (mut x, mut y) = (x, y);
        let mut s = self.side;
        self.levels[0][(y * s + x) as usize] = true;
        for l in 1..self.levels.len() {
            let (cx, cy) = (x & !1, y & !1);
            let all = [(cx, cy), (cx + 1, cy), (cx, cy + 1), (cx + 1, cy + 1)]
                .iter()
                .all(|&(a, b)| self.levels[l - 1][(b * s + a) as usize]);
            if !all {
                return;
            }
            x /= 2;
            y /= 2;
            s /= 2;
            self.levels[l][(y * s + x) as usize] = true;
        }
    }

    /// Whether every pixel of `[x0, x1) × [y0, y1)` is covered (an empty rectangle is).
    #[must_use]
    pub fn covered(&self, x0: u32, y0: u32, x1: u32, y1: u32) -> bool {
        let (x1, y1) = (x1.min(self.side), y1.min(self.side));
        if x0 >= x1 || y0 >= y1 {
            return true;
        }
        self.covered_in(self.levels.len() - 1, 0, 0, [x0, y0, x1, y1])
    }

    fn covered_in(&self, level: usize, x: u32, y: u32, r: [u32; 4]) -> bool {
        let s = self.side >> level;
        let span = 1 << level;
        let (nx0, ny0) = (x * span, y * span);
        let (nx1, ny1) = (nx0 + span, ny0 + span);
        if nx1 <= r[0] || ny1 <= r[1] || nx0 >= r[2] || ny0 >= r[3] {
            return true; // disjoint: nothing of the rectangle here
        }
        if self.levels[level][(y * s + x) as usize] {
            return true;
        }
        if level == 0 {
            return false;
        }
        (0..4).all(|k| self.covered_in(level - 1, 2 * x + (k & 1), 2 * y + (k >> 1), r))
    }
}

/// What [`render_front_to_back`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FrontToBackStats {
    /// Voxels drawn.
    pub drawn: usize,
    /// Nodes (branches or leaves) skipped because their projection was already covered.
    pub culled: usize,
}

/// Draws the octree front to back: a node whose projected bounding rectangle is fully covered
/// in the [`CoverageQuadtree`] is skipped with its subtree; a voxel writes only pixels not yet
/// covered (the depth buffer used as a one-bit mask: every fragment has the same depth, no depth
/// comparison between voxels), and the quadtree records what it covered.
pub fn render_front_to_back(
    tree: &Octree,
    camera: &Camera,
    target: &mut Framebuffer,
) -> FrontToBackStats {
    let (w, h) = (target.width(), target.height());
    let mut coverage = CoverageQuadtree::new(w, h);
    let mut stats = FrontToBackStats::default();
    let view_projection = camera.view_projection();
    let shader = VoxelShader {
        view_projection,
        constant_depth: true,
    };
    let state = PipelineState {
        cull: CullMode::Back,
        depth_compare: Some(DepthCompare::Less),
        depth_write: true,
        ..PipelineState::default()
    };
    // The pixel rectangle a box covers on screen (the whole screen when it crosses the eye
    // plane).
    let rect = |v: &Voxel| -> [u32; 4] {
        let (mut lo, mut hi) = (
            glam::Vec2::splat(f32::INFINITY),
            glam::Vec2::splat(-f32::INFINITY),
        );
        for k in 0..8 {
            let corner = v.min
                + Vec3::new((k & 1) as f32, ((k >> 1) & 1) as f32, ((k >> 2) & 1) as f32) * v.size;
            let clip = view_projection * corner.extend(1.0);
            if clip.w <= 1e-6 {
                return [0, 0, w, h];
            }
            let ndc = clip.truncate().truncate() / clip.w;
            let px = glam::Vec2::new(
                (ndc.x + 1.0) * 0.5 * w as f32,
                (1.0 - ndc.y) * 0.5 * h as f32,
            );
            lo = lo.min(px);
            hi = hi.max(px);
        }
        let clamp = |x: f32, m: u32| x.clamp(0.0, m as f32) as u32;
        [
            clamp(lo.x.floor(), w),
            clamp(lo.y.floor(), h),
            clamp(hi.x.ceil() + 1.0, w),
            clamp(hi.y.ceil() + 1.0, h),
        ]
    };
    tree.walk(
        &tree.root,
        tree.origin,
        tree.size,
        camera.eye,
        true,
        &mut |v, leaf| {
            let r = rect(&v);
            if coverage.covered(r[0], r[1], r[2], r[3]) {
                stats.culled += 1;
                return false;
            }
            if leaf {
                let (mut vertices, mut indices) = (Vec::new(), Vec::new());
                voxel_faces(&v, &mut vertices, &mut indices);
                draw(target, &shader, &state, &vertices, &indices);
                stats.drawn += 1;
                for y in r[1]..r[3] {
                    for x in r[0]..r[2] {
                        if target.depth(x, y).is_some_and(|d| d < 1.0) {
                            coverage.mark(x, y);
                        }
                    }
                }
            }
            true
        },
    );
    stats
}
