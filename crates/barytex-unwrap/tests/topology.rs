//! Topology of the generated shapes: Euler characteristic, genus, boundary loops, welding.

use barytex_unwrap::{TopologyOptions, UnwrapError, UnwrapMesh, mesh_topology, shapes};
use glam::DVec3;
use proptest::prelude::*;

fn single_component(mesh: &UnwrapMesh) -> barytex_unwrap::Component {
    let t = mesh_topology(mesh, TopologyOptions::default()).expect("manifold");
    let mut c = t.components();
    assert_eq!(c.len(), 1);
    c.pop().expect("one")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn closed_shapes_have_their_genus(rings in 2u32..20, segments in 3u32..30, k in 1u32..6) {
        let s = single_component(&shapes::sphere(rings, segments));
        prop_assert_eq!((s.euler_characteristic, s.boundary_loops, s.genus()), (2, 0, 0));
        let t = single_component(&shapes::torus(1.0, 0.3, segments, rings + 1));
        prop_assert_eq!((t.euler_characteristic, t.boundary_loops, t.genus()), (0, 0, 1));
        let c = single_component(&shapes::cube(k));
        prop_assert_eq!((c.euler_characteristic, c.boundary_loops, c.genus()), (2, 0, 0));
    }

    #[test]
    fn grids_are_disks_with_their_whole_rim_as_the_boundary(n in 1u32..20, m in 1u32..20) {
        let g = shapes::grid(n, m, |x, y| x * y);
        let c = single_component(&g);
        prop_assert!(c.is_disk());
        let t = mesh_topology(&g, TopologyOptions::default()).expect("manifold");
        let loops = t.boundary_loops();
        prop_assert_eq!(loops.len(), 1);
        prop_assert_eq!(loops[0].len() as u32, 2 * (n + m));
    }
}

#[test]
fn welding_joins_a_split_cube() {
    // A cube as glTF stores it: each face with its own four vertices.
    let cube = shapes::cube(1);
    let mut p = Vec::new();
    let mut t = Vec::new();
    for tri in cube.triangles() {
        let base = p.len() as u32;
        p.extend(tri.iter().map(|&v| cube.positions()[v as usize]));
        t.push([base, base + 1, base + 2]);
    }
    let split = UnwrapMesh::new(p, t).expect("valid");
    let apart = mesh_topology(&split, TopologyOptions { weld: false }).expect("manifold");
    assert_eq!(apart.components().len(), 12);
    let welded = single_component(&split);
    assert_eq!((welded.euler_characteristic, welded.genus()), (2, 0));
}

#[test]
fn non_manifold_input_names_the_edge_or_vertex() {
    let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::NEG_Y, DVec3::Z];
    let fin = UnwrapMesh::new(p.clone(), vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]]).expect("valid");
    let e = mesh_topology(&fin, TopologyOptions::default());
    assert_eq!(e, Err(UnwrapError::NonManifoldEdge { a: 0, b: 1 }));
    assert!(e.expect_err("non-manifold").to_string().contains("(0, 1)"));
    let bowtie = UnwrapMesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::NEG_X, DVec3::NEG_Y],
        vec![[0, 1, 2], [0, 3, 4]],
    )
    .expect("valid");
    let e = mesh_topology(&bowtie, TopologyOptions::default());
    assert_eq!(e, Err(UnwrapError::NonManifoldVertex { vertex: 0 }));
}
