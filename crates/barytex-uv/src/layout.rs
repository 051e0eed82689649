//! UV-layout pictures (feature `layout`): a mesh's uv wireframe drawn with tiny-skia over a
//! checker (or the caller's texture), seams in their own colour.
//!
//! A **seam** edge is one whose two triangles disagree about the uvs at its two (welded,
//! bit-equal) positions, or a boundary edge (one triangle), or a non-manifold edge (more than
//! two): the texture is discontinuous across it, and each side's copy is drawn. The uv square
//! fills the picture inside a margin (so seams on its border show whole): `x` grows with `u`, `y`
//! with `v` (uv `(0, 0)` at the top-left, as glTF); [`LayoutOptions::pixel`] gives the place.
//!
//! ```
//! use barytex_uv::layout::{LayoutOptions, draw_uv_layout};
//!
//! let sphere = barytex_uv::mesh::sphere(16, 8).expect("valid");
//! let picture = draw_uv_layout(&sphere, 128, &LayoutOptions::default()).expect("within limits");
//! assert_eq!((picture.width(), picture.height()), (128, 128));
//! ```

use std::collections::HashMap;
use std::path::Path;

use glam::{Vec2, Vec3};
use tiny_skia::{
    Color, FilterQuality, LineCap, Paint, PathBuilder, Pixmap, PixmapPaint, PremultipliedColorU8,
    Stroke, Transform,
};

use crate::UvError;
use crate::mesh::TriMesh;

/// The largest picture side [`draw_uv_layout`] draws (64 Mi pixels, 256 MiB).
pub const MAX_LAYOUT_SIZE: u32 = 8192;

/// How a layout is drawn.
#[derive(Clone, Copy, Debug)]
pub struct LayoutOptions<'a> {
    /// Drawn stretched over the whole picture instead of the checker, when given.
    pub texture: Option<&'a Pixmap>,
    /// Checker cells per side (≥ 1).
    pub checker_cells: u32,
    /// The checker's two colours.
    pub checker: [Color; 2],
    /// Colour of ordinary edges.
    pub wire: Color,
    /// Colour of seam edges.
    pub seam: Color,
    /// Width of ordinary edges in pixels.
    pub wire_width: f32,
    /// Width of seam edges in pixels.
    pub seam_width: f32,
    /// Pixels between the picture's border and the uv square (white there).
    pub margin: u32,
}

impl LayoutOptions<'_> {
    /// Where uv `uv` lands in a `size × size` picture (pixel units, `(0, 0)` the top-left
    /// corner of the top-left pixel).
    ///
    /// ```
    /// use barytex_uv::layout::LayoutOptions;
    /// use glam::Vec2;
    ///
    /// let options = LayoutOptions { margin: 6, ..LayoutOptions::default() };
    /// assert_eq!(options.pixel(Vec2::ZERO, 512), Vec2::splat(6.0));
    /// assert_eq!(options.pixel(Vec2::ONE, 512), Vec2::splat(506.0));
    /// ```
    #[must_use]
    pub fn pixel(&self, uv: Vec2, size: u32) -> Vec2 {
        let margin = self.margin_for(size) as f32;
        Vec2::splat(margin) + uv * (size as f32 - 2.0 * margin)
    }

    /// The margin, reduced so that at least one pixel of uv square remains.
    fn margin_for(&self, size: u32) -> u32 {
        self.margin.min(size.saturating_sub(1) / 2)
    }
}

impl Default for LayoutOptions<'_> {
    /// An 8 × 8 light-grey checker, dark-blue wire 1 px, red seams 2.5 px, a 6 px margin.
    fn default() -> Self {
        Self {
            texture: None,
            checker_cells: 8,
            checker: [
                Color::from_rgba8(236, 236, 236, 255),
                Color::from_rgba8(204, 204, 204, 255),
            ],
            wire: Color::from_rgba8(30, 50, 110, 255),
            seam: Color::from_rgba8(220, 30, 30, 255),
            wire_width: 1.0,
            seam_width: 2.5,
            margin: 6,
        }
    }
}

/// A mesh's edges in uv, split into ordinary (each drawn once) and seam edges (each side's
/// copy).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct UvEdges {
    /// Edges whose two triangles agree on the uvs (one copy each).
    pub wire: Vec<[Vec2; 2]>,
    /// Seam, boundary and non-manifold edges, one copy per triangle using them.
    pub seams: Vec<[Vec2; 2]>,
}

/// A position as exact bits (`−0` made `+0`), the welding key.
fn weld_key(p: Vec3) -> [u32; 3] {
    (p + Vec3::ZERO).to_array().map(f32::to_bits)
}

/// Splits the mesh's edges into ordinary and seam edges (see the module docs). Triangles with an
/// index out of range are ignored.
///
/// ```
/// // An open plane: the square's border is its only seam, 4 × 2 edges.
/// let plane = barytex_uv::mesh::plane(2, 2).expect("valid");
/// let edges = barytex_uv::layout::uv_edges(&plane);
/// assert_eq!(edges.seams.len(), 8);
/// assert_eq!(edges.wire.len(), 16 - 8);
/// ```
#[must_use]
pub fn uv_edges(mesh: &TriMesh) -> UvEdges {
    // Per welded edge (keys in order), the uvs each triangle gives its two ends (in key order).
    type Key = [u32; 3];
    let mut edges: HashMap<(Key, Key), Vec<[Vec2; 2]>> = HashMap::new();
    let vertex = |i: u32| {
        let i = i as usize;
        Some((*mesh.positions.get(i)?, *mesh.uvs.get(i)?))
    };
    for &[a, b, c] in &mesh.indices {
        let (Some(a), Some(b), Some(c)) = (vertex(a), vertex(b), vertex(c)) else {
            continue;
        };
        for (from, to) in [(a, b), (b, c), (c, a)] {
            let (kf, kt) = (weld_key(from.0), weld_key(to.0));
            let (key, uvs) = if kf <= kt {
                ((kf, kt), [from.1, to.1])
            } else {
                ((kt, kf), [to.1, from.1])
            };
            edges.entry(key).or_default().push(uvs);
        }
    }
    let mut result = UvEdges::default();
    for uses in edges.into_values() {
        match uses.as_slice() {
            [one, two] if one == two => result.wire.push(*one),
            _ => result.seams.extend(uses),
        }
    }
    // Deterministic pictures and tests: the map's order is not.
    let order = |e: &[Vec2; 2]| [e[0].x, e[0].y, e[1].x, e[1].y];
    let by_order = |x: &[Vec2; 2], y: &[Vec2; 2]| order(x).partial_cmp(&order(y));
    let compare =
        |x: &[Vec2; 2], y: &[Vec2; 2]| by_order(x, y).unwrap_or(core::cmp::Ordering::Equal);
    result.wire.sort_by(compare);
    result.seams.sort_by(compare);
    result
}

fn premultiplied(color: Color) -> PremultipliedColorU8 {
    color.premultiply().to_color_u8()
}

/// Draws `mesh`'s uv layout into a `size × size` picture: a white margin, the uv square's
/// background (checker or `options.texture`), ordinary edges in `options.wire`, seam edges on top in `options.seam`.
/// Edges with a non-finite uv are skipped.
///
/// # Errors
/// [`UvError::OutOfRange`] for `size = 0`, `checker_cells = 0` or a negative width;
/// [`UvError::NonFinite`] for a non-finite width; [`UvError::TooLarge`] for `size >`
/// [`MAX_LAYOUT_SIZE`].
///
/// ```
/// use barytex_uv::layout::{LayoutOptions, draw_uv_layout};
///
/// let cube = barytex_uv::mesh::cube(2).expect("valid");
/// assert!(draw_uv_layout(&cube, 0, &LayoutOptions::default()).is_err());
/// assert!(draw_uv_layout(&cube, 100_000, &LayoutOptions::default()).is_err());
/// ```
pub fn draw_uv_layout(
    mesh: &TriMesh,
    size: u32,
    options: &LayoutOptions<'_>,
) -> Result<Pixmap, UvError> {
    if size > MAX_LAYOUT_SIZE {
        return Err(UvError::TooLarge {
            what: "layout size",
            requested: u64::from(size),
            limit: u64::from(MAX_LAYOUT_SIZE),
        });
    }
    for (what, value) in [
        ("layout size", size),
        ("checker cells", options.checker_cells),
    ] {
        if value == 0 {
            return Err(UvError::OutOfRange { what, value: 0.0 });
        }
    }
    for (what, width) in [
        ("wire width", options.wire_width),
        ("seam width", options.seam_width),
    ] {
        if !width.is_finite() {
            return Err(UvError::NonFinite { what });
        }
        if width < 0.0 {
            return Err(UvError::OutOfRange {
                what,
                value: f64::from(width),
            });
        }
    }
    let mut pixmap = Pixmap::new(size, size).ok_or(UvError::TooLarge {
        what: "layout size",
        requested: u64::from(size),
        limit: u64::from(MAX_LAYOUT_SIZE),
    })?;
    pixmap.fill(Color::WHITE);
    let margin = options.margin_for(size);
    let inner = size - 2 * margin;
    match options.texture {
        Some(texture) => {
            let scale = |side: u32| inner as f32 / side as f32;
            pixmap.draw_pixmap(
                0,
                0,
                texture.as_ref(),
                &PixmapPaint {
                    quality: FilterQuality::Bilinear,
                    ..PixmapPaint::default()
                },
                Transform::from_scale(scale(texture.width()), scale(texture.height()))
                    .post_translate(margin as f32, margin as f32),
                None,
            );
        }
        None => {
            let colours = options.checker.map(premultiplied);
            let cells = u64::from(options.checker_cells.min(inner));
            let cell = |i: u32| u64::from(i - margin) * cells / u64::from(inner);
            let pixels = pixmap.pixels_mut();
            for y in margin..margin + inner {
                for x in margin..margin + inner {
                    let parity = (cell(x) + cell(y)) % 2;
                    pixels[(y * size + x) as usize] = colours[usize::from(parity == 1)];
                }
            }
        }
    }
    let edges = uv_edges(mesh);
    for (segments, colour, width) in [
        (&edges.wire, options.wire, options.wire_width),
        (&edges.seams, options.seam, options.seam_width),
    ] {
        let mut path = PathBuilder::new();
        for &[a, b] in segments {
            if a.is_finite() && b.is_finite() {
                let (a, b) = (options.pixel(a, size), options.pixel(b, size));
                path.move_to(a.x, a.y);
                path.line_to(b.x, b.y);
            }
        }
        let Some(path) = path.finish() else {
            continue;
        };
        let mut paint = Paint::default();
        paint.set_color(colour);
        paint.anti_alias = true;
        // Round caps close the corners where seam segments meet at an angle.
        let stroke = Stroke {
            width,
            line_cap: LineCap::Round,
            ..Stroke::default()
        };
        pixmap.stroke_path(&path, &paint, &stroke, Transform::identity(), None);
    }
    Ok(pixmap)
}

/// Writes `pixmap` as a PNG file.
///
/// # Errors
/// [`UvError::Io`] when encoding or writing fails.
pub fn write_png(pixmap: &Pixmap, path: &Path) -> Result<(), UvError> {
    pixmap
        .save_png(path)
        .map_err(|error| UvError::Io(format!("{}: {error}", path.display())))
}
