//! Every sample model in the shared fixtures loads, and known content comes out right.

mod common;

use std::path::{Path, PathBuf};

use barytex_gltf::{LoadOptions, Projection, Scene, SceneError, load_path};

fn model(name: &str, variant: &str, file: &str) -> Option<PathBuf> {
    let p = common::fixtures()?
        .join("gltf")
        .join(name)
        .join(variant)
        .join(file);
    p.exists().then_some(p)
}

fn load(p: &Path) -> Scene {
    match load_path(p, &LoadOptions::default()) {
        Ok(s) => s,
        Err(e) => panic!("{}: {e}", p.display()),
    }
}

/// Loads every variant of a model present; `check` runs on each.
fn each_variant(name: &str, file_stem: &str, check: impl Fn(&Path, &Scene)) {
    let mut n = 0;
    for (variant, ext) in [
        ("glTF", "gltf"),
        ("glTF-Binary", "glb"),
        ("glTF-Embedded", "gltf"),
    ] {
        if let Some(p) = model(name, variant, &format!("{file_stem}.{ext}")) {
            let s = load(&p);
            check(&p, &s);
            n += 1;
        }
    }
    if common::fixtures().is_some() {
        assert!(n > 0, "no variant of {name} found");
    }
}

#[test]
fn every_sample_model_loads() {
    let models = common::sample_models();
    let mut failures = Vec::new();
    for p in &models {
        match load_path(p, &LoadOptions::default()) {
            Ok(s) => println!(
                "ok {}: {} instances, {} triangles, {} images decoded, {} warnings",
                p.display(),
                s.instances.len(),
                s.triangle_count(),
                s.stats.images_decoded,
                s.warnings.len()
            ),
            Err(e) => failures.push(format!("{}: {e}", p.display())),
        }
    }
    println!(
        "{} sample files loaded, {} failed",
        models.len() - failures.len(),
        failures.len()
    );
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn box_has_twelve_triangles() {
    each_variant("Box", "Box", |p, s| {
        assert_eq!(s.triangle_count(), 12, "{}", p.display());
        assert_eq!(s.instances.len(), 1);
        let prim = &s.instances[0].mesh.primitives[0];
        assert_eq!(prim.positions.len(), 24);
        assert!(prim.normals.is_some());
    });
    each_variant("BoxInterleaved", "BoxInterleaved", |p, s| {
        assert_eq!(s.triangle_count(), 12, "{}", p.display());
    });
}

#[test]
fn triangle_without_indices() {
    each_variant(
        "TriangleWithoutIndices",
        "TriangleWithoutIndices",
        |p, s| {
            assert_eq!(s.triangle_count(), 1, "{}", p.display());
            assert_eq!(s.instances[0].mesh.primitives[0].triangles, vec![[0, 1, 2]]);
        },
    );
}

#[test]
fn sparse_accessor_is_applied() {
    each_variant("SimpleSparseAccessor", "SimpleSparseAccessor", |p, s| {
        use glam::Vec3;
        let positions = &s.instances[0].mesh.primitives[0].positions;
        // The sparse substitution replaces vertices 8, 10 and 12 (values read from the .bin).
        assert_eq!(positions.len(), 14);
        assert_eq!(positions[8], Vec3::new(1.0, 2.0, 0.0), "{}", p.display());
        assert_eq!(positions[10], Vec3::new(3.0, 3.0, 0.0));
        assert_eq!(positions[12], Vec3::new(5.0, 4.0, 0.0));
    });
}

#[test]
fn multiple_scenes() {
    each_variant("MultipleScenes", "MultipleScenes", |p, s| {
        assert_eq!(s.scene_count, 2, "{}", p.display());
        let other = load_path(
            p,
            &LoadOptions {
                scene: Some(1),
                ..LoadOptions::default()
            },
        );
        assert!(matches!(other, Ok(ref o) if o.scene_index == Some(1)));
        let bad = load_path(
            p,
            &LoadOptions {
                scene: Some(2),
                ..LoadOptions::default()
            },
        );
        assert!(matches!(bad, Err(SceneError::Invalid { .. })));
    });
}

#[test]
fn two_cameras() {
    each_variant("Cameras", "Cameras", |p, s| {
        assert_eq!(s.cameras.len(), 2, "{}", p.display());
        assert!(
            s.cameras
                .iter()
                .any(|c| matches!(c.projection, Projection::Perspective { .. }))
        );
        assert!(
            s.cameras
                .iter()
                .any(|c| matches!(c.projection, Projection::Orthographic { .. }))
        );
    });
}

#[test]
fn vertex_colors() {
    each_variant("BoxVertexColors", "BoxVertexColors", |p, s| {
        let with_colors = s
            .instances
            .iter()
            .flat_map(|i| &i.mesh.primitives)
            .filter(|pr| pr.colors0.is_some())
            .count();
        assert!(with_colors > 0, "{}: no COLOR_0", p.display());
    });
}

#[test]
fn primitive_modes() {
    each_variant("MeshPrimitiveModes", "MeshPrimitiveModes", |p, s| {
        use barytex_gltf::Topology;
        // 18 TRIANGLES indices → 6, 6 strip indices → 4, 8 fan indices → 6 (from the file).
        let count = |t: Topology| -> Vec<usize> {
            s.instances
                .iter()
                .flat_map(|i| &i.mesh.primitives)
                .filter(|pr| pr.topology == t)
                .map(|pr| pr.triangles.len())
                .collect()
        };
        assert_eq!(count(Topology::Triangles), vec![6], "{}", p.display());
        assert_eq!(count(Topology::TriangleStrip), vec![4]);
        assert_eq!(count(Topology::TriangleFan), vec![6]);
        assert_eq!(s.triangle_count(), 16);
        // POINTS, LINES, LINE_LOOP, LINE_STRIP: kept with their index lists, no triangles.
        assert_eq!(s.stats.primitives_points_lines, 4);
        assert_eq!(s.stats.primitives_loaded, 7);
        assert!(!s.warnings.iter().any(|w| w.contains("not triangles")));
        let kept = |t: Topology| -> Vec<(usize, usize)> {
            s.instances
                .iter()
                .flat_map(|i| &i.mesh.primitives)
                .filter(|pr| pr.topology == t)
                .map(|pr| (pr.indices.len(), pr.triangles.len()))
                .collect()
        };
        // The file's index counts: 7 points, 12 line indices (6 segments), 7 for the loop and
        // the strip.
        assert_eq!(kept(Topology::Points), vec![(7, 0)]);
        assert_eq!(kept(Topology::Lines), vec![(12, 0)]);
        assert_eq!(kept(Topology::LineLoop), vec![(7, 0)]);
        assert_eq!(kept(Topology::LineStrip), vec![(7, 0)]);
        assert_eq!(count(Topology::Triangles), vec![6]);
    });
}

#[test]
fn odd_file_names_load() {
    each_variant("Unicode❤♻Test", "Unicode❤♻Test", |p, s| {
        assert!(s.triangle_count() > 0, "{}", p.display());
        assert!(
            s.stats.images_decoded > 0,
            "{}: texture not decoded",
            p.display()
        );
    });
    each_variant("Box With Spaces", "Box With Spaces", |p, s| {
        assert!(s.triangle_count() > 0, "{}", p.display());
        assert!(s.stats.images_decoded > 0, "{}", p.display());
    });
}
