//! UV-layout pictures: the PNG has the requested size, seams are found where the generators put
//! them, seam pixels are drawn in the seam colour and the background elsewhere, limits refuse.
#![cfg(feature = "layout")]

use barytex_uv::UvError;
use barytex_uv::layout::{LayoutOptions, MAX_LAYOUT_SIZE, draw_uv_layout, uv_edges};
use barytex_uv::mesh;
use glam::Vec2;
use tiny_skia::{Color, Pixmap};

/// Whether the pixel under uv `uv` is (mostly) the seam colour.
fn is_seam_red(picture: &Pixmap, uv: Vec2) -> bool {
    // The pixel whose centre is nearest, on the uv square's side at its far borders.
    let at = (LayoutOptions::default().pixel(uv, picture.width()) - 0.5).floor();
    let p = picture
        .pixel(at.x as u32, at.y as u32)
        .expect("inside")
        .demultiply();
    p.red() > 150 && p.green() < 110 && p.blue() < 110
}

#[test]
fn png_has_the_requested_size() {
    let torus = mesh::torus(24, 12, 1.0, 0.4).expect("valid");
    for size in [1, 17, 256] {
        let picture = draw_uv_layout(&torus, size, &LayoutOptions::default()).expect("drawn");
        let png = picture.encode_png().expect("encoded");
        let decoded = Pixmap::decode_png(&png).expect("decoded");
        assert_eq!((decoded.width(), decoded.height()), (size, size));
    }
}

#[test]
fn cube_atlas_seams_are_drawn_in_the_seam_colour() {
    let cube = mesh::cube(3).expect("valid");
    let size = 384;
    let picture = draw_uv_layout(&cube, size, &LayoutOptions::default()).expect("drawn");
    // The atlas cells (1/3 on a side, two rows) meet at u = 1/3, 2/3 and v = 1/3: seams (each
    // face has its own vertices); the atlas's outline is a seam too, drawn whole inside the
    // margin on the picture's border.
    for i in 0..=50 {
        let t = i as f32 / 50.0;
        let s = t * 2.0 / 3.0;
        for uv in [
            Vec2::new(1.0 / 3.0, s),
            Vec2::new(2.0 / 3.0, s),
            Vec2::new(t, 1.0 / 3.0),
            Vec2::new(0.0, s),
            Vec2::new(1.0, s),
            Vec2::new(t, 0.0),
            Vec2::new(t, 2.0 / 3.0),
        ] {
            assert!(is_seam_red(&picture, uv), "{uv}");
        }
    }
    // Away from every edge, the checker's colours (in a cell between grid lines, and in the
    // atlas's unused bottom third).
    for uv in [
        Vec2::new(0.05, 0.12),
        Vec2::new(0.4, 0.2),
        Vec2::new(0.8, 0.8),
    ] {
        let at = LayoutOptions::default().pixel(uv, size);
        let p = picture
            .pixel(at.x as u32, at.y as u32)
            .expect("inside")
            .demultiply();
        assert!(
            [236, 204].contains(&p.red()) && p.red() == p.green(),
            "{uv}: {p:?}"
        );
    }
    // The margin is white.
    let corner = picture.pixel(1, 1).expect("inside").demultiply();
    assert_eq!(
        (corner.red(), corner.green(), corner.blue()),
        (255, 255, 255)
    );
}

#[test]
fn sphere_and_torus_seams_lie_where_the_generators_cut() {
    let torus = mesh::torus(24, 12, 1.0, 0.4).expect("valid");
    let edges = uv_edges(&torus);
    // u = 0 and u = 1 columns (12 edges each), v = 0 and v = 1 rows (24 each).
    assert_eq!(edges.seams.len(), 2 * (12 + 24));
    for [a, b] in &edges.seams {
        let on = |f: fn(glam::Vec2) -> f32, value| f(*a) == value && f(*b) == value;
        assert!(
            on(|p| p.x, 0.0) || on(|p| p.x, 1.0) || on(|p| p.y, 0.0) || on(|p| p.y, 1.0),
            "{a} {b}"
        );
    }
    let sphere = mesh::sphere(16, 8).expect("valid");
    let edges = uv_edges(&sphere);
    // The seam columns, plus the pole spokes (each pole vertex has its own u per column).
    for [a, b] in &edges.seams {
        let at_seam = (a.x == 0.0 && b.x == 0.0) || (a.x == 1.0 && b.x == 1.0);
        let at_pole = [a.y, b.y].iter().any(|&v| v == 0.0 || v == 1.0);
        assert!(at_seam || at_pole, "{a} {b}");
    }
    assert!(edges.seams.iter().any(|e| e[0].x == 0.0 && e[1].x == 0.0));
    assert!(edges.seams.iter().any(|e| e[0].x == 1.0 && e[1].x == 1.0));
    // Away from the seams, edges are shared: ordinary wire.
    assert!(!edges.wire.is_empty());
}

#[test]
fn a_caller_texture_replaces_the_checker() {
    let mut texture = Pixmap::new(4, 4).expect("non-zero");
    texture.fill(Color::from_rgba8(10, 200, 10, 255));
    let options = LayoutOptions {
        texture: Some(&texture),
        ..LayoutOptions::default()
    };
    let plane = mesh::plane(2, 2).expect("valid");
    let picture = draw_uv_layout(&plane, 64, &options).expect("drawn");
    let p = picture.pixel(22, 14).expect("inside").demultiply();
    assert_eq!((p.red(), p.green(), p.blue()), (10, 200, 10));
    // The plane's border is a seam (boundary edges).
    assert!(is_seam_red(&picture, Vec2::new(0.5, 0.0)));
    assert!(is_seam_red(&picture, Vec2::new(1.0, 0.3)));
}

#[test]
fn limits_are_refused() {
    let plane = mesh::plane(1, 1).expect("valid");
    let defaults = LayoutOptions::default();
    assert!(matches!(
        draw_uv_layout(&plane, 0, &defaults),
        Err(UvError::OutOfRange { .. })
    ));
    assert!(matches!(
        draw_uv_layout(&plane, MAX_LAYOUT_SIZE + 1, &defaults),
        Err(UvError::TooLarge { .. })
    ));
    assert!(matches!(
        draw_uv_layout(&plane, u32::MAX, &defaults),
        Err(UvError::TooLarge { .. })
    ));
    let zero_cells = LayoutOptions {
        checker_cells: 0,
        ..defaults
    };
    assert!(matches!(
        draw_uv_layout(&plane, 8, &zero_cells),
        Err(UvError::OutOfRange { .. })
    ));
    let nan_width = LayoutOptions {
        wire_width: f32::NAN,
        ..defaults
    };
    assert!(matches!(
        draw_uv_layout(&plane, 8, &nan_width),
        Err(UvError::NonFinite { .. })
    ));
    // A mesh with bad indices or non-finite uvs is drawn without them, not refused.
    let mut broken = mesh::plane(2, 2).expect("valid");
    broken.indices.push([0, 1, 1000]);
    broken.uvs[0].x = f32::NAN;
    assert!(draw_uv_layout(&broken, 16, &defaults).is_ok());
}
