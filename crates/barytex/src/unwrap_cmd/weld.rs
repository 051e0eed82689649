//! One mesh's triangle primitives as one [`UnwrapMesh`]: positions welded (equal f32 bits are
//! one vertex, `−0` as `+0`), so that triangles a glTF splits at normal or uv seams are
//! neighbours again and a chart may cross those seams.

use std::collections::HashMap;

use barytex_gltf::Primitive;
use barytex_unwrap::UnwrapMesh;
use glam::{DVec3, Vec3};

/// A welded mesh and where its triangles came from.
pub(crate) struct Welded {
    /// The mesh to unwrap.
    pub(crate) mesh: UnwrapMesh,
    /// For each of its triangles: the primitive (index into the slice given to [`weld`]) and
    /// the triangle within it.
    pub(crate) source: Vec<(u32, u32)>,
}

fn key(p: Vec3) -> [u32; 3] {
    (p + Vec3::ZERO).to_array().map(f32::to_bits)
}

/// Welds the primitives' positions and gathers their triangles.
pub(crate) fn weld(primitives: &[&Primitive]) -> Result<Welded, String> {
    let mut index: HashMap<[u32; 3], u32> = HashMap::new();
    let mut positions: Vec<DVec3> = Vec::new();
    let mut triangles = Vec::new();
    let mut source = Vec::new();
    for (slot, primitive) in primitives.iter().enumerate() {
        let mut welded = Vec::with_capacity(primitive.positions.len());
        for &p in &primitive.positions {
            let next = u32::try_from(positions.len())
                .map_err(|_| "more than 2^32 vertices in one mesh".to_owned())?;
            let id = *index.entry(key(p)).or_insert_with(|| {
                positions.push(p.as_dvec3());
                next
            });
            welded.push(id);
        }
        for (t, corners) in primitive.triangles.iter().enumerate() {
            let w = corners.map(|i| welded.get(i as usize).copied());
            let [Some(a), Some(b), Some(c)] = w else {
                return Err(format!(
                    "primitive {slot}: triangle {t} names a vertex that does not exist"
                ));
            };
            triangles.push([a, b, c]);
            source.push((slot as u32, t as u32));
        }
    }
    let mesh = UnwrapMesh::new(positions, triangles).map_err(|e| e.to_string())?;
    Ok(Welded { mesh, source })
}
