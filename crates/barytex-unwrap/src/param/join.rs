//! Which triangles are neighbours: twins across manifold, consistently oriented, non-seam edges.

use crate::UnwrapError;
use crate::topology::NONE;

/// Half-edge twins between usable faces: `twins[3 f + i]` is the half-edge of another usable
/// face running the other way along the same (welded) edge when exactly one such exists, no
/// other face uses the edge, and it is not a seam; [`NONE`] otherwise. Also returns the number
/// of half-edges left unjoined because their edge is non-manifold.
pub(super) fn join_faces(
    tris: &[[u32; 3]],
    usable: &[bool],
    weld: &[u32],
    seams: &[[u32; 2]],
) -> Result<(Vec<u32>, usize), UnwrapError> {
    let key = |a: u32, b: u32| (u64::from(a) << 32) | u64::from(b);
    let mut keys: Vec<(u64, u32)> =
        crate::alloc::try_vec_with_capacity(3 * tris.len(), "half-edges")?;
    for (t, tri) in tris.iter().enumerate() {
        if usable[t] {
            for i in 0..3 {
                keys.push((key(tri[i], tri[(i + 1) % 3]), (3 * t + i) as u32));
            }
        }
    }
    keys.sort_unstable();
    let mut seam_set = std::collections::HashSet::with_capacity(seams.len());
    for s in seams {
        let (a, b) = (weld[s[0] as usize], weld[s[1] as usize]);
        seam_set.insert(key(a.min(b), a.max(b)));
    }
    let mut twins = vec![NONE; 3 * tris.len()];
    let mut non_manifold = 0;
    let range = |k: u64| {
        let lo = keys.partition_point(|e| e.0 < k);
        let hi = keys.partition_point(|e| e.0 <= k);
        lo..hi
    };
    for &(k, h) in &keys {
        let (a, b) = ((k >> 32) as u32, k as u32);
        let same = range(k);
        let other = range(key(b, a));
        if same.len() == 1 && other.len() == 1 {
            if !seam_set.contains(&key(a.min(b), a.max(b))) {
                twins[h as usize] = keys[other.start].1;
            }
        } else if same.len() > 1 || other.len() > 1 {
            non_manifold += 1;
        }
    }
    Ok((twins, non_manifold))
}
