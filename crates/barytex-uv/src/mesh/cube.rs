//! The cube, its six faces in a 3 × 2 atlas of square cells.

use glam::{DVec2, DVec3};

use super::TriMesh;
use super::builder::{Builder, Vertex, at_least, fraction, within_limit};
use crate::UvError;

/// The faces in atlas order (`+x, −x, +y, −y, +z, −z`), each as (outward normal, `∂p/∂u`);
/// `∂p/∂v` is `∂p/∂u × n`, which keeps every face unmirrored with `v` down.
const FACES: [(DVec3, DVec3); 6] = [
    (DVec3::X, DVec3::NEG_Z),
    (DVec3::NEG_X, DVec3::Z),
    (DVec3::Y, DVec3::X),
    (DVec3::NEG_Y, DVec3::X),
    (DVec3::Z, DVec3::X),
    (DVec3::NEG_Z, DVec3::NEG_X),
];

/// The cube `[−1, 1]³`, each face an `n × n` grid of quads with its own vertices (the edges are
/// seams), laid out in a 3 × 2 atlas of square cells `1/3` on a side (so no face is stretched;
/// the texture's bottom third, `v > 2/3`, is unused): face `k` of `+x, −x, +y, −y, +z, −z`
/// fills the cell in column `k mod 3`, row `k div 3`, i.e. `u ∈ [(k mod 3)/3, (k mod 3 + 1)/3]`,
/// `v ∈ [(k div 3)/3, (k div 3 + 1)/3]`. The side faces read upright (`v` down is `−y`).
///
/// # Errors
/// [`UvError::OutOfRange`] for `n = 0`; [`UvError::TooLarge`] when `6(n + 1)²` exceeds
/// [`MAX_VERTICES`](super::MAX_VERTICES).
///
/// ```
/// let cube = barytex_uv::mesh::cube(2).expect("valid");
/// assert_eq!(cube.positions.len(), 6 * 9);
/// assert_eq!(cube.indices.len(), 6 * 8);
/// ```
pub fn cube(n: u32) -> Result<TriMesh, UvError> {
    at_least("cube n", n, 1)?;
    let side = u128::from(n) + 1;
    let vertices = within_limit(6 * side * side)?;
    let mut builder = Builder::with_capacity(vertices);
    // (2i − n)/n: exactly symmetric (c(n − i) = −c(i)), so faces meet at bit-identical positions.
    let centred = |i: u32| (2.0 * f64::from(i) - f64::from(n)) / f64::from(n);
    for (k, &(normal, tu)) in FACES.iter().enumerate() {
        let tv = tu.cross(normal);
        let (column, row) = ((k % 3) as f64, (k / 3) as f64);
        builder.grid(n, n, |i, j| Vertex {
            position: normal + tu * centred(i) + tv * centred(j),
            normal,
            dpdu: tu,
            dpdv: tv,
            uv: DVec2::new(
                (column + fraction(i, n)) / 3.0,
                (row + fraction(j, n)) / 3.0,
            ),
        });
    }
    Ok(builder.finish())
}
