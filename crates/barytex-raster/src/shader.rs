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
