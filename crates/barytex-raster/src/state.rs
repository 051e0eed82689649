//! Fixed-function state of a draw: culling, winding, viewport, scissor, depth, blending,
//! interpolation and derivative modes.

/// The depth test: when a fragment's depth passes against the stored one.
///
/// The eight comparisons of Vulkan's `VkCompareOp`, WebGPU's `GPUCompareFunction` and OpenGL's
/// `glDepthFunc`, with IEEE 754 comparisons: a NaN depth fails every test but `NotEqual` and
/// `Always`.
///
/// ```
/// use barytex_raster::DepthCompare;
///
/// assert!(DepthCompare::Less.passes(0.25, 0.5));
/// assert!(!DepthCompare::Less.passes(0.5, 0.5));
/// assert!(DepthCompare::LessEqual.passes(0.5, 0.5));
/// assert!(DepthCompare::NotEqual.passes(f32::NAN, 0.5));
/// assert!(!DepthCompare::GreaterEqual.passes(f32::NAN, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DepthCompare {
    /// Never passes.
    Never,
    /// `fragment < stored` (the default).
    #[default]
    Less,
    /// `fragment == stored`.
    Equal,
    /// `fragment <= stored`.
    LessEqual,
    /// `fragment > stored`.
    Greater,
    /// `fragment != stored`.
    NotEqual,
    /// `fragment >= stored`.
    GreaterEqual,
    /// Always passes.
    Always,
}

impl DepthCompare {
    /// Whether a fragment at depth `fragment` passes against `stored`.
    #[inline]
    #[must_use]
    pub fn passes(self, fragment: f32, stored: f32) -> bool {
        match self {
            Self::Never => false,
            Self::Less => fragment < stored,
            Self::Equal => fragment == stored,
            Self::LessEqual => fragment <= stored,
            Self::Greater => fragment > stored,
            Self::NotEqual => fragment != stored,
            Self::GreaterEqual => fragment >= stored,
            Self::Always => true,
        }
    }
}

/// Which faces are discarded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CullMode {
    /// Draw both faces.
    None,
    /// Discard back faces (the default).
    #[default]
    Back,
    /// Discard front faces.
    Front,
}

/// Which winding (in a y-up frame, as in clip space) is the front.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FrontFace {
    /// Counter-clockwise is front (glTF, OpenGL, wgpu's default).
    #[default]
    Ccw,
    /// Clockwise is front.
    Cw,
}

/// How varyings are interpolated across a triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Interpolation {
    /// Perspective-correct (the default): the varying is affine on the triangle in 3D.
    #[default]
    Perspective,
    /// Affine in screen space: wrong foreshortening under perspective (Buss, *3D Computer
    /// Graphics*, 2003, Figure V.2), kept for comparison.
    Affine,
    /// Perspective-correct at the ends of `span`-pixel runs of a row (aligned to multiples of
    /// `span`), affine in between: one division per span instead of one per pixel, with an
    /// error that grows with the span and the foreshortening (measured in the report). The
    /// derivatives stay exact. `span` is clamped to 2..=256.
    AffineSpans {
        /// Pixels per span (8, 16 and 32 are the classic choices).
        span: u32,
    },
}

/// How colours are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Blend {
    /// The fragment replaces the pixel.
    #[default]
    Replace,
    /// Porter–Duff "over" on premultiplied colour: `dst = src + dst·(1 − src.a)`.
    Over,
}

/// The screen rectangle that normalized device coordinates map onto, and the depth range.
///
/// Nothing is checked, and nothing panics: a NaN or infinite field, or one that puts a vertex
/// beyond [`MAX_COORDINATE`](crate::MAX_COORDINATE) pixels (a huge width, a far-off origin),
/// makes the triangle `degenerate` in [`DrawStats`](crate::DrawStats) (dropped); a zero width or
/// height too (zero area); a negative width or height gives an empty rectangle
/// `[x, x + width)`, so nothing is written; a NaN depth range gives NaN fragment depths, which
/// fail every depth test but `NotEqual` and `Always`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Viewport {
    /// Left edge in pixels.
    pub x: f32,
    /// Top edge in pixels.
    pub y: f32,
    /// Width in pixels.
    pub width: f32,
    /// Height in pixels.
    pub height: f32,
    /// Depth of NDC z = 0.
    pub min_depth: f32,
    /// Depth of NDC z = 1.
    pub max_depth: f32,
}

impl Viewport {
    /// The whole target, depth [0, 1].
    ///
    /// ```
    /// use barytex_raster::Viewport;
    ///
    /// let v = Viewport::full(640, 480);
    /// assert_eq!((v.x, v.y, v.width, v.height), (0.0, 0.0, 640.0, 480.0));
    /// assert_eq!((v.min_depth, v.max_depth), (0.0, 1.0));
    /// ```
    #[must_use]
    pub fn full(width: u32, height: u32) -> Self {
        Self {
            x: 0.0,
            y: 0.0,
            width: width as f32,
            height: height as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        }
    }
}

/// A pixel rectangle `[x0, x1) × [y0, y1)` outside which nothing is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Scissor {
    /// Left (inclusive).
    pub x0: u32,
    /// Top (inclusive).
    pub y0: u32,
    /// Right (exclusive).
    pub x1: u32,
    /// Bottom (exclusive).
    pub y1: u32,
}

/// Everything but the shader and the geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PipelineState {
    /// Face culling.
    pub cull: CullMode,
    /// Front winding.
    pub front_face: FrontFace,
    /// `None`: the whole target.
    pub viewport: Option<Viewport>,
    /// `None`: no scissor.
    pub scissor: Option<Scissor>,
    /// Depth test (`None`: off); a fragment passes when `compare(fragment, stored)` holds.
    pub depth_compare: Option<DepthCompare>,
    /// Whether passing fragments write their depth.
    pub depth_write: bool,
    /// Colour blending.
    pub blend: Blend,
    /// Varying interpolation.
    pub interpolation: Interpolation,
    /// In a multisampled target: `false` shades once per pixel and writes the colour to every
    /// covered sample (MSAA: edges anti-aliased, shading not); `true` shades every covered
    /// sample on its own (supersampling: everything anti-aliased, at the cost of a shading per
    /// sample). Ignored with one sample per pixel.
    pub sample_shading: bool,
}

impl Default for PipelineState {
    /// Back-face culling, counter-clockwise front, the whole target, depth test `Less` with
    /// writes, replace, perspective-correct, shading once per pixel.
    fn default() -> Self {
        Self {
            cull: CullMode::Back,
            front_face: FrontFace::Ccw,
            viewport: None,
            scissor: None,
            depth_compare: Some(DepthCompare::Less),
            depth_write: true,
            blend: Blend::Replace,
            interpolation: Interpolation::Perspective,
            sample_shading: false,
        }
    }
}
