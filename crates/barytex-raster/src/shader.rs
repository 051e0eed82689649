//! The `Shader` seam: vertex → clip position + varying; fragment → colour or discard.

use barytex_interp::Interpolate;
use glam::{DVec2, UVec2, Vec3, Vec4};

use crate::state::Interpolation;

/// A programmable pipeline stage pair. Uniforms live in the implementing type.
///
/// ```
/// use barytex_raster::{Fragment, Shader};
/// use glam::{Vec3, Vec4};
///
/// /// Flat-coloured triangles with positions already in clip space.
/// struct Solid(Vec4);
///
/// impl Shader for Solid {
///     type Vertex = Vec3;
///     type Varying = f32; // nothing interesting to interpolate
///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) {
///         (v.extend(1.0), 0.0)
///     }
///     fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> {
///         Some(self.0)
///     }
/// }
/// ```
pub trait Shader: Sync {
    /// The per-vertex input.
    type Vertex: Sync;
    /// What the vertex stage hands to the fragment stage, interpolated across the triangle.
    type Varying: Interpolate + Send + Sync;

    /// The clip-space position `(x, y, z, w)` (visible: `−w ≤ x, y ≤ w`, `0 ≤ z ≤ w`) and the
    /// varying of a vertex.
    fn vertex(&self, vertex: &Self::Vertex) -> (Vec4, Self::Varying);

    /// The linear-light, straight-alpha colour of a fragment, or `None` to discard it.
    fn fragment(&self, fragment: &Fragment<'_, Self::Varying>) -> Option<Vec4>;

    /// Whether single-sampled draws hand this shader's fragments over two at a time, through
    /// [`fragment_pair`](Self::fragment_pair) (a piece's odd last fragment through
    /// [`fragment`](Self::fragment)). Worth it for a shader whose fragment is one long
    /// dependency chain (a texture lookup's footprint, level, addresses, loads, filtering):
    /// two chains written side by side overlap in the processor where two calls one after the
    /// other do not. The image is the same either way.
    const PAIRS: bool = false;

    /// The colours of two fragments of one triangle at different pixels:
    /// `[self.fragment(a), self.fragment(b)]`, which an override must return too (interleaving
    /// the two computations is the point of overriding it).
    ///
    /// ```
    /// use barytex_raster::{Fragment, Shader};
    /// use glam::{Vec3, Vec4};
    ///
    /// struct Grey;
    /// impl Shader for Grey {
    ///     type Vertex = Vec3;
    ///     type Varying = f32;
    ///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) { (v.extend(1.0), v.x) }
    ///     fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
    ///         Some(Vec4::new(f.varying, f.varying, f.varying, 1.0))
    ///     }
    ///     const PAIRS: bool = true;
    ///     fn fragment_pair(&self, a: &Fragment<'_, f32>, b: &Fragment<'_, f32>) -> [Option<Vec4>; 2] {
    ///         // Both varyings at once (a real shader would interleave longer work).
    ///         let [x, y] = [a.varying, b.varying];
    ///         [Some(Vec4::new(x, x, x, 1.0)), Some(Vec4::new(y, y, y, 1.0))]
    ///     }
    /// }
    /// ```
    #[inline(always)]
    fn fragment_pair(
        &self,
        a: &Fragment<'_, Self::Varying>,
        b: &Fragment<'_, Self::Varying>,
    ) -> [Option<Vec4>; 2] {
        [self.fragment(a), self.fragment(b)]
    }

    /// Whether single-sampled draws hand this shader's fragments over four at a time, through
    /// [`fragment_quad`](Self::fragment_quad) (a piece's last one to three through
    /// [`fragment_pair`](Self::fragment_pair) and [`fragment`](Self::fragment)). Worth it for
    /// a shader whose per-fragment arithmetic can run over four fragments per instruction
    /// (arrays of four that the compiler vectorizes, as a texture lookup's coordinates). The
    /// image is the same either way.
    const QUADS: bool = false;

    /// The colours of four fragments of one triangle piece at different pixels:
    /// `f.map(|f| self.fragment(f))`, which an override must return too.
    ///
    /// ```
    /// use barytex_raster::{Fragment, Shader};
    /// use glam::{Vec3, Vec4};
    ///
    /// struct Grey;
    /// impl Shader for Grey {
    ///     type Vertex = Vec3;
    ///     type Varying = f32;
    ///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) { (v.extend(1.0), v.x) }
    ///     fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
    ///         Some(Vec4::new(f.varying, f.varying, f.varying, 1.0))
    ///     }
    ///     const QUADS: bool = true;
    ///     fn fragment_quad(&self, f: &[Fragment<'_, f32>; 4]) -> [Option<Vec4>; 4] {
    ///         // The four varyings as one array (a real shader would do longer work on it).
    ///         let v = f.map(|f| f.varying);
    ///         v.map(|x| Some(Vec4::new(x, x, x, 1.0)))
    ///     }
    /// }
    /// ```
    #[inline(always)]
    fn fragment_quad(&self, f: &[Fragment<'_, Self::Varying>; 4]) -> [Option<Vec4>; 4] {
        let [a, b] = self.fragment_pair(&f[0], &f[1]);
        let [c, d] = self.fragment_pair(&f[2], &f[3]);
        [a, b, c, d]
    }
}

/// What the fragment stage sees at one pixel. The varying is interpolated eagerly; its screen
/// derivatives [`ddx`](Self::ddx) and [`ddy`](Self::ddy) only when asked for (most shaders never
/// read them, and they cost two more interpolations).
#[derive(Clone, Copy, Debug)]
pub struct Fragment<'a, V> {
    /// The varying at the pixel centre (perspective-correct unless the state says affine).
    pub varying: V,
    /// Depth in the viewport's depth range.
    pub depth: f32,
    /// The pixel, (0, 0) at the top-left.
    pub pixel: UVec2,
    /// Whether the triangle faces the viewer (after the pipeline's `front_face`).
    pub front_facing: bool,
    /// The samples of the pixel the triangle covers, bit `k` for sample `k` (`1` in a
    /// single-sampled target; with per-sample shading, only the sample being shaded).
    pub coverage: u32,
    pub(crate) lambda: [f64; 3],
    pub(crate) piece: &'a PieceContext<V>,
}

/// What the derivatives of a fragment need from its triangle piece.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PieceContext<V> {
    /// The input triangle's varyings.
    pub(crate) varyings: [V; 3],
    /// Screen gradients of the piece's barycentrics.
    pub(crate) grads: [DVec2; 3],
    /// 1/w at the piece's vertices.
    pub(crate) inv_w: [f64; 3],
    /// The piece's vertices as barycentrics of the input triangle (`None`: the identity).
    pub(crate) bary: Option<[Vec3; 3]>,
    pub(crate) interpolation: Interpolation,
}

impl<V: Copy> PieceContext<V> {
    /// Weights over the input vertices for the piece weights `w`.
    #[inline]
    pub(crate) fn input_weights(&self, w: [f64; 3]) -> [f32; 3] {
        match &self.bary {
            None => w.map(|x| x as f32),
            Some(bary) => {
                let v = (0..3).fold(glam::DVec3::ZERO, |acc, i| acc + bary[i].as_dvec3() * w[i]);
                [v.x as f32, v.y as f32, v.z as f32]
            }
        }
    }

    /// Interpolation weights over the piece's vertices at screen barycentrics `lambda`
    /// (perspective-correct for affine spans: these are the span ends and the derivatives).
    #[inline]
    pub(crate) fn weights(&self, lambda: [f64; 3]) -> [f64; 3] {
        match self.interpolation {
            Interpolation::Affine => lambda,
            Interpolation::Perspective | Interpolation::AffineSpans { .. } => {
                let q: [f64; 3] = core::array::from_fn(|i| lambda[i] * self.inv_w[i]);
                let inv_d = 1.0 / (q[0] + q[1] + q[2]);
                q.map(|x| x * inv_d)
            }
        }
    }

    /// [`weights`](Self::weights) at four points, lane by lane (each lane the same operations:
    /// the same weights).
    #[inline(always)]
    #[allow(
        clippy::needless_range_loop,
        reason = "lane loops: they unroll and vectorize"
    )]
    pub(crate) fn weights_quad(&self, lambda: [[f64; 3]; 4]) -> [[f64; 3]; 4] {
        match self.interpolation {
            Interpolation::Affine => lambda,
            Interpolation::Perspective | Interpolation::AffineSpans { .. } => {
                // Plain lane loops: `array::map` and `from_fn` closures stayed out of line.
                let q = self.perspective_terms_quad(&lambda);
                let mut inv_d = [0.0; 4];
                for k in 0..4 {
                    inv_d[k] = 1.0 / (q[0][k] + q[1][k] + q[2][k]);
                }
                let mut weights = [[0.0; 3]; 4];
                for k in 0..4 {
                    for i in 0..3 {
                        weights[k][i] = q[i][k] * inv_d[k];
                    }
                }
                weights
            }
        }
    }

    /// `qᵢ = λᵢ/wᵢ` at four points: `q[i][k]` for vertex `i` at point `k` (lanes innermost).
    #[inline(always)]
    #[allow(
        clippy::needless_range_loop,
        reason = "lane loops: they unroll and vectorize"
    )]
    fn perspective_terms_quad(&self, lambda: &[[f64; 3]; 4]) -> [[f64; 4]; 3] {
        let mut q = [[0.0; 4]; 3];
        for i in 0..3 {
            for k in 0..4 {
                q[i][k] = lambda[k][i] * self.inv_w[i];
            }
        }
        q
    }

    /// [`derivative_weights_xy`](Self::derivative_weights_xy) of [`divide_terms`] at four
    /// points with perspective, lane by lane: `[point][axis][vertex]`. Each lane computes the
    /// same operations in the same order as one point alone (the sums `(a + b) + c`, as `sum`
    /// from −0.0 adds them), so the weights are identical.
    ///
    /// [`divide_terms`]: Self::divide_terms
    #[inline(always)]
    #[allow(
        clippy::needless_range_loop,
        reason = "lane loops: they unroll and vectorize"
    )]
    fn derivative_weights_quad(&self, lambda: &[[f64; 3]; 4]) -> [[[f64; 3]; 2]; 4] {
        let q = self.perspective_terms_quad(lambda);
        let (mut d, mut d2) = ([0.0; 4], [0.0; 4]);
        for k in 0..4 {
            d[k] = q[0][k] + q[1][k] + q[2][k];
            d2[k] = d[k] * d[k];
        }
        // The piece's own terms: the gradients over w and their sums, per axis.
        let mut qd = [[0.0; 2]; 3];
        for i in 0..3 {
            for axis in 0..2 {
                qd[i][axis] = self.grads[i][axis] * self.inv_w[i];
            }
        }
        let mut dd = [0.0; 2];
        for axis in 0..2 {
            dd[axis] = qd[0][axis] + qd[1][axis] + qd[2][axis];
        }
        let mut w = [[[0.0; 3]; 2]; 4];
        for axis in 0..2 {
            for i in 0..3 {
                for k in 0..4 {
                    w[k][axis][i] = (qd[i][axis] * d[k] - q[i][k] * dd[axis]) / d2[k];
                }
            }
        }
        w
    }

    /// What the weights' derivatives along both axes share: with perspective, `qᵢ = λᵢ/wᵢ`,
    /// `D = Σq` and `D²`; `None` for affine interpolation.
    #[inline]
    fn divide_terms(&self, lambda: [f64; 3]) -> Option<([f64; 3], f64, f64)> {
        match self.interpolation {
            Interpolation::Affine => None,
            Interpolation::Perspective | Interpolation::AffineSpans { .. } => {
                let q: [f64; 3] = core::array::from_fn(|i| lambda[i] * self.inv_w[i]);
                let d = q.iter().sum::<f64>();
                Some((q, d, d * d))
            }
        }
    }

    /// The weights' derivatives along `axis` (0 = x, 1 = y) from [`divide_terms`]: zero-sum
    /// weights, `(q′ᵢ·D − qᵢ·D′)/D²` with perspective.
    ///
    /// [`divide_terms`]: Self::divide_terms
    #[inline]
    fn derivative_weights(&self, terms: Option<([f64; 3], f64, f64)>, axis: usize) -> [f64; 3] {
        let g: [f64; 3] = core::array::from_fn(|i| self.grads[i][axis]);
        match terms {
            None => g,
            Some((q, d, d2)) => {
                let qd: [f64; 3] = core::array::from_fn(|i| g[i] * self.inv_w[i]);
                let dd = qd.iter().sum::<f64>();
                core::array::from_fn(|i| (qd[i] * d - q[i] * dd) / d2)
            }
        }
    }

    /// [`derivative_weights`](Self::derivative_weights) along x and along y at once. On
    /// x86-64 the two axes run in the lanes of SSE2 registers (the gradients are stored as
    /// `(x, y)` pairs): each lane computes the same IEEE operations in the same order as one
    /// axis alone, so the weights are identical, with half the divisions.
    #[inline]
    fn derivative_weights_xy(&self, terms: Option<([f64; 3], f64, f64)>) -> [[f64; 3]; 2] {
        #[cfg(target_arch = "x86_64")]
        if let Some((q, d, d2)) = terms {
            use safe_arch::{add_m128d, div_m128d, m128d, mul_m128d, set_splat_m128d, sub_m128d};
            let qd: [m128d; 3] = core::array::from_fn(|i| {
                let g = m128d::from_array([self.grads[i].x, self.grads[i].y]);
                mul_m128d(g, set_splat_m128d(self.inv_w[i]))
            });
            // `qd.iter().sum()` starts from −0.0, which leaves every first term unchanged.
            let dd = add_m128d(add_m128d(qd[0], qd[1]), qd[2]);
            let (d, d2) = (set_splat_m128d(d), set_splat_m128d(d2));
            let w: [[f64; 2]; 3] = core::array::from_fn(|i| {
                let num = sub_m128d(mul_m128d(qd[i], d), mul_m128d(set_splat_m128d(q[i]), dd));
                div_m128d(num, d2).to_array()
            });
            return [0, 1].map(|axis| [w[0][axis], w[1][axis], w[2][axis]]);
        }
        [
            self.derivative_weights(terms, 0),
            self.derivative_weights(terms, 1),
        ]
    }
}

impl<V: Interpolate> Fragment<'_, V> {
    /// The varying's change per pixel to the right: the exact derivative of the interpolation
    /// at the pixel centre (analytic, not a 2×2-quad difference).
    ///
    /// ```
    /// use std::sync::Mutex;
    ///
    /// use barytex_raster::{Fragment, Framebuffer, PipelineState, Shader, TargetLimits, draw};
    /// use glam::{Vec3, Vec4};
    ///
    /// /// Interpolates clip-space x and records its four derivatives at every pixel.
    /// struct Derivatives(Mutex<Vec<[f32; 4]>>);
    /// impl Shader for Derivatives {
    ///     type Vertex = Vec3;
    ///     type Varying = f32;
    ///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) { (v.extend(1.0), v.x) }
    ///     fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
    ///         let d = [f.ddx(), f.ddy(), f.ddx_quad(), f.ddy_quad()];
    ///         self.0.lock().expect("not poisoned").push(d);
    ///         Some(Vec4::ONE)
    ///     }
    /// }
    /// let tri = [Vec3::new(-1.0, -1.0, 0.5), Vec3::new(3.0, -1.0, 0.5), Vec3::new(-1.0, 3.0, 0.5)];
    /// let shader = Derivatives(Mutex::new(Vec::new()));
    /// let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default())?;
    /// draw(&mut fb, &shader, &PipelineState::default(), &tri, &[0, 1, 2]);
    /// let seen = shader.0.into_inner().expect("not poisoned");
    /// assert_eq!(seen.len(), 64);
    /// // x spans 2 units of clip space over 8 pixels: 0.25 per pixel right, nothing down; with
    /// // w = 1 everywhere the quad differences agree with the analytic derivatives.
    /// for [dx, dy, qx, qy] in seen {
    ///     assert!((dx - 0.25).abs() < 1e-6 && dy.abs() < 1e-6, "{dx} {dy}");
    ///     assert!((qx - 0.25).abs() < 1e-6 && qy.abs() < 1e-6, "{qx} {qy}");
    /// }
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    #[must_use]
    pub fn ddx(&self) -> V {
        self.along(0)
    }

    /// The varying's change per pixel down.
    #[must_use]
    pub fn ddy(&self) -> V {
        self.along(1)
    }

    /// The derivative along one axis (0 = x, 1 = y).
    fn along(&self, axis: usize) -> V {
        let piece = self.piece;
        let w = piece.derivative_weights(piece.divide_terms(self.lambda), axis);
        V::combine3(piece.varyings, piece.input_weights(w))
    }

    /// `(ddx(), ddy())`, the same values, for about the price of one: the perspective divide's
    /// terms are shared by both axes.
    ///
    /// ```
    /// use std::sync::atomic::{AtomicUsize, Ordering};
    ///
    /// use barytex_raster::{Fragment, Framebuffer, PipelineState, Shader, TargetLimits, draw};
    /// use glam::{Vec3, Vec4};
    ///
    /// /// A perspective triangle (w varies) whose fragments check both forms agree.
    /// struct Both(AtomicUsize);
    /// impl Shader for Both {
    ///     type Vertex = Vec3;
    ///     type Varying = f32;
    ///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) {
    ///         (Vec4::new(v.x, v.y, 0.5, 1.0 + 0.25 * v.y), v.x * v.y)
    ///     }
    ///     fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
    ///         assert_eq!(f.derivatives(), (f.ddx(), f.ddy()));
    ///         self.0.fetch_add(1, Ordering::Relaxed);
    ///         Some(Vec4::ONE)
    ///     }
    /// }
    /// let tri = [Vec3::new(-1.0, -1.0, 0.0), Vec3::new(3.0, -1.0, 0.0), Vec3::new(-1.0, 3.0, 0.0)];
    /// let shader = Both(AtomicUsize::new(0));
    /// let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default())?;
    /// draw(&mut fb, &shader, &PipelineState::default(), &tri, &[0, 1, 2]);
    /// assert!(shader.0.into_inner() > 0);
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    #[must_use]
    #[inline]
    pub fn derivatives(&self) -> (V, V) {
        self.derivatives_of(|v| *v)
    }

    /// [`derivatives`](Self::derivatives) of one part of the varying, `part(varying)`: the same
    /// values as that part of `derivatives()` when the varying interpolates its parts
    /// independently (as structs of vectors do), without interpolating the rest.
    ///
    /// ```
    /// use barytex_raster::{Fragment, Framebuffer, PipelineState, Shader, TargetLimits, draw};
    /// use glam::{Vec2, Vec3, Vec4};
    ///
    /// /// Checks the uv part's derivatives against those of the whole (uv, depth) varying.
    /// struct Part;
    /// impl Shader for Part {
    ///     type Vertex = Vec3;
    ///     type Varying = (Vec2, f32);
    ///     fn vertex(&self, v: &Vec3) -> (Vec4, (Vec2, f32)) {
    ///         (Vec4::new(v.x, v.y, 0.5, 1.0 + 0.25 * v.y), (Vec2::new(v.x, v.y * v.y), v.z))
    ///     }
    ///     fn fragment(&self, f: &Fragment<'_, (Vec2, f32)>) -> Option<Vec4> {
    ///         let (dx, dy) = f.derivatives();
    ///         assert_eq!(f.derivatives_of(|v| v.0), (dx.0, dy.0));
    ///         Some(Vec4::ONE)
    ///     }
    /// }
    /// let tri = [Vec3::new(-1.0, -1.0, 0.0), Vec3::new(3.0, -1.0, 0.0), Vec3::new(-1.0, 3.0, 0.0)];
    /// let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default())?;
    /// draw(&mut fb, &Part, &PipelineState::default(), &tri, &[0, 1, 2]);
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    #[must_use]
    // Always: a shader that reads one part calls it once per fragment, and out of line (the
    // closure, the fragment and two results through memory) it cost the unlit Avocado frame a
    // fifth of its wall time although it ran fewer instructions.
    #[inline(always)]
    pub fn derivatives_of<T: Interpolate>(&self, part: impl Fn(&V) -> T) -> (T, T) {
        let piece = self.piece;
        let terms = piece.divide_terms(self.lambda);
        let v = &piece.varyings;
        let parts = [part(&v[0]), part(&v[1]), part(&v[2])];
        let [wx, wy] = piece.derivative_weights_xy(terms);
        (
            T::combine3(parts, piece.input_weights(wx)),
            T::combine3(parts, piece.input_weights(wy)),
        )
    }

    /// [`derivatives_of`](Self::derivatives_of) at four fragments of one triangle piece (the
    /// four of a [`Shader::fragment_quad`] call): the same values, with the perspective terms
    /// and the derivative weights of the four computed lane by lane, which the compiler turns
    /// into four fragments per instruction where the fragment loop is built for AVX2.
    /// Fragments of different pieces are taken one by one.
    ///
    /// ```
    /// use std::sync::atomic::{AtomicUsize, Ordering};
    ///
    /// use barytex_raster::{Fragment, Framebuffer, PipelineState, Shader, TargetLimits, draw};
    /// use glam::{Vec3, Vec4};
    ///
    /// /// A perspective triangle whose quads check the batched derivatives.
    /// struct Quads(AtomicUsize);
    /// impl Shader for Quads {
    ///     type Vertex = Vec3;
    ///     type Varying = f32;
    ///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) {
    ///         (Vec4::new(v.x, v.y, 0.5, 1.0 + 0.25 * v.y), v.x * v.y)
    ///     }
    ///     fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> {
    ///         Some(Vec4::ONE)
    ///     }
    ///     const QUADS: bool = true;
    ///     fn fragment_quad(&self, f: &[Fragment<'_, f32>; 4]) -> [Option<Vec4>; 4] {
    ///         let batched = Fragment::derivatives_of_quad(f, |v| *v);
    ///         for (fragment, d) in f.iter().zip(batched) {
    ///             assert_eq!(d, fragment.derivatives());
    ///         }
    ///         self.0.fetch_add(4, Ordering::Relaxed);
    ///         [Some(Vec4::ONE); 4]
    ///     }
    /// }
    /// let tri = [Vec3::new(-1.0, -1.0, 0.0), Vec3::new(3.0, -1.0, 0.0), Vec3::new(-1.0, 3.0, 0.0)];
    /// let shader = Quads(AtomicUsize::new(0));
    /// let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default())?;
    /// draw(&mut fb, &shader, &PipelineState::default(), &tri, &[0, 1, 2]);
    /// assert!(shader.0.into_inner() > 0);
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    ///
    /// [`Shader::fragment_quad`]: crate::Shader::fragment_quad
    #[must_use]
    #[inline(always)]
    pub fn derivatives_of_quad<T: Interpolate>(
        f: &[Self; 4],
        part: impl Fn(&V) -> T,
    ) -> [(T, T); 4] {
        let piece = f[0].piece;
        let perspective = !matches!(piece.interpolation, Interpolation::Affine);
        if !perspective || !f.iter().all(|x| core::ptr::eq(x.piece, piece)) {
            return [0, 1, 2, 3].map(|k| f[k].derivatives_of(&part));
        }
        let v = &piece.varyings;
        let parts = [part(&v[0]), part(&v[1]), part(&v[2])];
        let lambda = [f[0].lambda, f[1].lambda, f[2].lambda, f[3].lambda];
        let w = piece.derivative_weights_quad(&lambda);
        let along = |k: usize| {
            (
                T::combine3(parts, piece.input_weights(w[k][0])),
                T::combine3(parts, piece.input_weights(w[k][1])),
            )
        };
        [along(0), along(1), along(2), along(3)]
    }

    /// GPU-style x derivative: the difference with the other pixel of this pixel's 2×2 quad in
    /// the same row (its varying extrapolated from the triangle, as a helper invocation would
    /// compute it), `right − left`. Less accurate than [`ddx`](Self::ddx): it is the derivative
    /// half a pixel away, so on perspective-foreshortened surfaces it is off by the varying's
    /// second derivative; offered to compare with GPUs.
    #[must_use]
    pub fn ddx_quad(&self) -> V {
        self.quad_difference(0, self.pixel.x)
    }

    /// GPU-style y derivative within the 2×2 quad, `bottom − top`.
    #[must_use]
    pub fn ddy_quad(&self) -> V {
        self.quad_difference(1, self.pixel.y)
    }

    fn quad_difference(&self, axis: usize, coordinate: u32) -> V {
        // Even pixels pair with the next one, odd pixels with the previous one.
        let step = if coordinate.is_multiple_of(2) {
            1.0
        } else {
            -1.0
        };
        let partner: [f64; 3] =
            core::array::from_fn(|i| self.lambda[i] + self.piece.grads[i][axis] * step);
        let here = self.piece.weights(self.lambda);
        let there = self.piece.weights(partner);
        // (there − here)·step: zero-sum weights, one interpolation.
        let w: [f64; 3] = core::array::from_fn(|i| (there[i] - here[i]) * step);
        V::combine3(self.piece.varyings, self.piece.input_weights(w))
    }
}
