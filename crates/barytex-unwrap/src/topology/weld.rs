//! Welding: vertices at the same position become one.
//!
//! glTF splits a vertex wherever a normal or texture coordinate changes, so a cube arrives as
//! six disconnected squares; welding equal positions restores the surface's connectivity before
//! it is cut into charts again where the parameterization wants.

use std::collections::HashMap;

use glam::DVec3;

/// For each vertex, the lowest-indexed vertex at the same position (`-0.0` equals `0.0`).
/// Exact equality only: no tolerance, so two vertices are welded exactly when they are the same
/// point.
///
/// ```
/// use barytex_unwrap::weld_positions;
/// use glam::DVec3;
///
/// let p = [DVec3::ZERO, DVec3::X, DVec3::new(-0.0, 0.0, 0.0), DVec3::X];
/// assert_eq!(weld_positions(&p), vec![0, 1, 0, 1]);
/// ```
#[must_use]
pub fn weld_positions(positions: &[DVec3]) -> Vec<u32> {
    let mut first: HashMap<[u64; 3], u32> = HashMap::with_capacity(positions.len());
    positions
        .iter()
        .enumerate()
        .map(|(i, p)| {
            // Adding +0.0 turns -0.0 into +0.0 and changes nothing else.
            let key = [p.x + 0.0, p.y + 0.0, p.z + 0.0].map(f64::to_bits);
            *first.entry(key).or_insert(i as u32)
        })
        .collect()
}
