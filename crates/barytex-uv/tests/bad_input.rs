//! Bad input the other tests do not feed: inverse mappings outside their image, `to_f32` of
//! overflowing Jacobians, `reflect` and `singular_values` on non-finite values, distortion of
//! meshes with bad indices or NaN, `uv_edges` and `write_png` on bad input.

use barytex_uv::distortion::{MeshDistortion, singular_values};
use barytex_uv::environment::reflect;
use barytex_uv::mappings::{
    BoxFace, BoxMapping, Cylindrical, DUvJacobian, InverseUvMapping, Planar, SphereProjection,
    Spherical, Torus,
};
use barytex_uv::mesh;
use glam::{DMat2, DVec2, DVec3, Vec2, Vec3};

const NON_FINITE: [f32; 3] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];

fn bad_uvs() -> Vec<Vec2> {
    let mut out = Vec::new();
    for bad in NON_FINITE {
        out.extend([Vec2::new(bad, 0.5), Vec2::new(0.5, bad), Vec2::splat(bad)]);
    }
    out
}

#[test]
fn point_at_is_none_for_non_finite_uv() {
    let planar = Planar::new(Vec3::ZERO, Vec3::X, Vec3::Z).expect("valid");
    let cylinder = Cylindrical::new(1.0, 2.0).expect("valid");
    let torus = Torus::new(2.0, 0.5).expect("valid");
    let spheres = [
        Spherical::new(1.0, SphereProjection::Equirectangular).expect("valid"),
        Spherical::new(1.0, SphereProjection::EqualArea).expect("valid"),
    ];
    let mut inverses: Vec<&dyn InverseUvMapping> = vec![&planar, &cylinder, &torus];
    inverses.extend(spheres.iter().map(|s| s as &dyn InverseUvMapping));
    for (k, m) in inverses.iter().enumerate() {
        for uv in bad_uvs() {
            assert_eq!(m.point_at(uv), None, "mapping {k}, uv {uv}");
        }
        // A good uv has a finite point.
        assert!(
            m.point_at(Vec2::new(0.25, 0.5))
                .is_some_and(Vec3::is_finite),
            "mapping {k}"
        );
    }
    // The sphere: v outside [0, 1] has no point (u is periodic and may be anything finite).
    for sphere in &spheres {
        for v in [-1e-7, -1.0, 1.000_001, 2.0, f32::MAX, -f32::MAX] {
            assert_eq!(sphere.point_at(Vec2::new(0.5, v)), None, "v = {v}");
        }
        for v in [0.0, 1.0] {
            let p = sphere.point_at(Vec2::new(0.3, v)).expect("a pole");
            assert!((p.length() - 1.0).abs() < 1e-6, "{p}");
        }
        assert!(
            sphere
                .point_at(Vec2::new(1e30, 0.5))
                .is_some_and(Vec3::is_finite)
        );
    }
}

#[test]
fn box_point_at_is_none_for_non_finite_uv() {
    let b = BoxMapping::new(Vec3::ZERO, 2.0).expect("valid");
    for face in BoxFace::ALL {
        for uv in bad_uvs() {
            assert_eq!(b.point_at(face, uv), None, "{face:?} {uv}");
        }
        let p = b.point_at(face, Vec2::splat(0.5)).expect("the face centre");
        assert!(
            (p - face.normal()).abs().max_element() < 1e-6,
            "{face:?} {p}"
        );
        // A huge finite uv whose point overflows f32: None.
        assert_eq!(b.point_at(face, Vec2::splat(f32::MAX)), None, "{face:?}");
    }
}

#[test]
fn duv_jacobian_to_f32_needs_every_component_finite_in_f32() {
    let good = DUvJacobian {
        uv: DVec2::new(0.5, 0.25),
        du: DVec3::X,
        dv: DVec3::Y,
    };
    let j = good.to_f32().expect("finite");
    assert_eq!((j.uv, j.du, j.dv), (Vec2::new(0.5, 0.25), Vec3::X, Vec3::Y));
    let cases = [
        DUvJacobian {
            uv: DVec2::new(f64::NAN, 0.0),
            ..good
        },
        DUvJacobian {
            du: DVec3::new(0.0, f64::INFINITY, 0.0),
            ..good
        },
        DUvJacobian {
            dv: DVec3::splat(f64::NEG_INFINITY),
            ..good
        },
        // Finite in f64 but beyond f32: overflows to ∞ when rounded.
        DUvJacobian {
            du: DVec3::new(1e39, 0.0, 0.0),
            ..good
        },
        DUvJacobian {
            uv: DVec2::new(0.0, -1e300),
            ..good
        },
    ];
    for case in cases {
        assert_eq!(case.to_f32(), None, "{case:?}");
    }
    // Below f32's range it underflows to zero, which is finite.
    let tiny = DUvJacobian {
        dv: DVec3::splat(1e-60),
        ..good
    };
    assert_eq!(tiny.to_f32().map(|j| j.dv), Some(Vec3::ZERO));
}

#[test]
fn reflect_is_unchecked_but_never_panics() {
    // Finite: the mirror image, even for non-unit inputs (2 (n·v) n − v as written).
    assert_eq!(
        reflect(Vec3::Y, Vec3::new(1.0, 1.0, 0.0)),
        Vec3::new(-1.0, 1.0, 0.0)
    );
    assert_eq!(reflect(Vec3::ZERO, Vec3::X), -Vec3::X);
    // Non-finite in → non-finite out.
    for bad in NON_FINITE {
        let r = reflect(Vec3::new(bad, 0.0, 0.0), Vec3::Y);
        assert!(!r.is_finite(), "n.x = {bad}: {r}");
        let r = reflect(Vec3::Y, Vec3::new(0.0, bad, 0.0));
        assert!(!r.is_finite(), "v.y = {bad}: {r}");
    }
    // Huge finite values overflow to ∞ (or NaN), never a panic.
    let r = reflect(Vec3::splat(f32::MAX), Vec3::splat(f32::MAX));
    assert!(!r.is_finite(), "{r}");
}

#[test]
fn singular_values_of_non_finite_and_zero_matrices() {
    assert_eq!(singular_values(DMat2::ZERO), (0.0, 0.0));
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let m = DMat2::from_cols(DVec2::new(bad, 0.0), DVec2::new(0.0, 1.0));
        let (s1, s2) = singular_values(m);
        assert!(!s1.is_finite() || !s2.is_finite(), "{bad}: ({s1}, {s2})");
        let m = DMat2::from_cols(DVec2::new(1.0, 0.0), DVec2::new(0.0, bad));
        let (s1, s2) = singular_values(m);
        assert!(!s1.is_finite() || !s2.is_finite(), "{bad}: ({s1}, {s2})");
    }
    // A rank-one matrix: the second value is exactly 0.
    let (s1, s2) = singular_values(DMat2::from_cols(DVec2::new(3.0, 4.0), DVec2::ZERO));
    assert_eq!((s1, s2), (5.0, 0.0));
    // Huge finite entries do not overflow (hypot).
    let (s1, s2) = singular_values(DMat2::from_diagonal(DVec2::new(1e300, 1e300)));
    assert!(s1.is_finite() && s2.is_finite(), "({s1}, {s2})");
}

#[test]
fn mesh_distortion_skips_bad_triangles_and_counts_them() {
    let good = mesh::plane(2, 2).expect("valid");
    let reference = MeshDistortion::of(&good).expect("measurable");
    assert_eq!(reference.skipped, 0);
    let n = good.indices.len();
    // Out-of-range indices.
    let mut bad_index = good.clone();
    bad_index.indices.push([0, 1, u32::MAX]);
    bad_index.indices.push([u32::MAX; 3]);
    let d = MeshDistortion::of(&bad_index).expect("still measurable");
    assert_eq!((d.triangles, d.skipped), (n, 2));
    assert_eq!(d.area_mean, reference.area_mean);
    // Missing uvs (shorter uv array than positions): the triangles using them are skipped.
    let mut short_uvs = good.clone();
    short_uvs.uvs.truncate(1);
    assert_eq!(MeshDistortion::of(&short_uvs), None);
    // A NaN position or uv: that vertex's triangles are skipped.
    for poison in 0..2 {
        let mut nan = good.clone();
        if poison == 0 {
            nan.positions[0] = Vec3::NAN;
        } else {
            nan.uvs[0] = Vec2::new(f32::INFINITY, 0.0);
        }
        let d = MeshDistortion::of(&nan).expect("other triangles");
        let using = good.indices.iter().filter(|t| t.contains(&0)).count();
        assert!(using > 0);
        assert_eq!(
            (d.triangles, d.skipped),
            (n - using, using),
            "poison {poison}"
        );
        assert!(d.area_mean.is_finite() && d.angle_mean.is_finite(), "{d:?}");
    }
    // Every uv the same: zero uv area → None.
    let mut flat = good.clone();
    flat.uvs.iter_mut().for_each(|uv| *uv = Vec2::splat(0.5));
    assert_eq!(MeshDistortion::of(&flat), None);
    // No triangles at all.
    let mut empty = good;
    empty.indices.clear();
    assert_eq!(MeshDistortion::of(&empty), None);
}

#[test]
fn area_excess_ratio_is_infinite_or_nan_without_excess() {
    let plane = MeshDistortion::of(&mesh::plane(2, 2).expect("valid")).expect("measurable");
    let sphere = MeshDistortion::of(&mesh::sphere(16, 8).expect("valid")).expect("measurable");
    assert!(sphere.area_mean > 1.0 && plane.area_mean == 1.0);
    assert_eq!(sphere.area_excess_ratio(&plane), f64::INFINITY);
    assert!(plane.area_excess_ratio(&plane).is_nan());
    assert_eq!(plane.area_excess_ratio(&sphere), 0.0);
    assert_eq!(sphere.area_excess_ratio(&sphere), 1.0);
}

#[cfg(feature = "layout")]
mod layout {
    use barytex_uv::layout::{LayoutOptions, draw_uv_layout, uv_edges, write_png};
    use barytex_uv::{UvError, mesh};
    use glam::Vec2;

    #[test]
    fn uv_edges_ignore_triangles_with_bad_indices() {
        let good = mesh::plane(2, 2).expect("valid");
        let reference = uv_edges(&good);
        let mut bad = good;
        bad.indices.push([0, 1, u32::MAX]);
        bad.indices.push([u32::MAX, u32::MAX - 1, 7_000]);
        let edges = uv_edges(&bad);
        assert_eq!(edges.wire.len(), reference.wire.len());
        assert_eq!(edges.seams.len(), reference.seams.len());
        // Non-finite uvs are kept as edges by `uv_edges` and skipped when drawing.
        let mut nan = mesh::plane(2, 2).expect("valid");
        nan.uvs[0] = Vec2::NAN;
        let picture = draw_uv_layout(&nan, 32, &LayoutOptions::default());
        assert!(picture.is_ok());
    }

    #[test]
    fn write_png_failures_are_io_errors_naming_the_path() {
        let picture = draw_uv_layout(
            &mesh::plane(1, 1).expect("valid"),
            8,
            &LayoutOptions::default(),
        )
        .expect("small");
        let path = std::env::temp_dir()
            .join(format!("barytex-uv-no-such-dir-{}", std::process::id()))
            .join("layout.png");
        let r = write_png(&picture, &path);
        assert!(
            matches!(&r, Err(UvError::Io(message)) if message.contains("layout.png")),
            "{r:?}"
        );
        // A folder is not writable as a file.
        let r = write_png(&picture, &std::env::temp_dir());
        assert!(matches!(r, Err(UvError::Io(_))), "{r:?}");
    }
}
