//! The `extras.barytex_portal` convention: mirrors and target portals placed in world space,
//! the portal limit, and clear errors (by JSON pointer, never echoing the file's values) for
//! every malformed declaration.

use barytex_gltf::{LoadOptions, Portal, SceneError, SceneLimits, load_slice};
use glam::{Mat4, Vec3, Vec4};

/// A document whose nodes are `nodes` (a JSON array's items), all roots of scene 0.
fn document(nodes: &str, roots: &str) -> String {
    format!(
        r#"{{"asset": {{"version": "2.0"}}, "nodes": [{nodes}], "scenes": [{{"nodes": [{roots}]}}]}}"#
    )
}

fn load(nodes: &str, roots: &str) -> Result<Vec<Portal>, SceneError> {
    load_slice(document(nodes, roots).as_bytes(), &LoadOptions::default()).map(|s| s.portals)
}

const SQUARE: &str = "[[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]";

fn portal_node(body: &str) -> String {
    let comma = if body.is_empty() { "" } else { ", " };
    format!(r#"{{"extras": {{"barytex_portal": {{"polygon": {SQUARE}{comma}{body}}}}}}}"#)
}

#[test]
fn mirrors_reflect_about_their_world_plane() {
    let node = format!(
        r#"{{"name": "glass", "translation": [0, 0, -3], "rotation": [0, 0.70710677, 0, 0.70710677],
            "extras": {{"barytex_portal": {{"polygon": {SQUARE}, "mirror": true}}}}}}"#
    );
    let portals = load(&node, "0").expect("loads");
    assert_eq!(portals.len(), 1);
    let m = &portals[0];
    assert_eq!(
        (m.node, m.name.as_deref(), m.tint),
        (Some(0), Some("glass"), Vec4::ZERO)
    );
    // Turned a quarter about +y: the plane x = 0 moved to z = −3 … facing +x.
    let plane = m.plane().expect("a square");
    assert!(
        (plane - Vec4::new(1.0, 0.0, 0.0, 0.0)).abs().max_element() < 1e-6,
        "{plane}"
    );
    let image = m.transform.transform_point3(Vec3::new(2.0, 1.0, -3.5));
    assert!(
        (image - Vec3::new(-2.0, 1.0, -3.5)).length() < 1e-5,
        "{image}"
    );
    assert!(m.transform.determinant() < 0.0);
}

#[test]
fn targets_map_the_target_nodes_frame_onto_the_portals() {
    // The portal at z = −5 shows what is around node 2, 100 units along x (a child of node 1).
    let portal = format!(
        r#"{{"translation": [0, 0, -5], "extras": {{"barytex_portal": {{"polygon": {SQUARE},
            "target": 2, "tint": [0.5, 0.5, 1, 0.25]}}}}}}"#
    );
    let nodes = format!(
        r#"{portal}, {{"translation": [100, 0, 0], "children": [2]}}, {{"translation": [0, 0, -5]}}"#
    );
    let portals = load(&nodes, "0, 1").expect("loads");
    let p = &portals[0];
    assert_eq!(p.tint, Vec4::new(0.5, 0.5, 1.0, 0.25));
    assert_eq!(p.polygon[0], Vec3::new(-1.0, -1.0, -5.0));
    // A point beside node 2 appears as far beside the portal.
    let seen = p.transform.transform_point3(Vec3::new(100.5, 1.0, -9.0));
    assert!((seen - Vec3::new(0.5, 1.0, -9.0)).length() < 1e-5, "{seen}");
    assert_eq!(
        p.transform,
        Mat4::from_translation(Vec3::new(-100.0, 0.0, 0.0))
    );
}

#[test]
fn a_mirroring_node_keeps_the_front_it_names() {
    let plain = load(&portal_node(r#""mirror": true"#), "0").expect("loads");
    let node = format!(
        r#"{{"scale": [-1, 1, 1], "extras": {{"barytex_portal": {{"polygon": {SQUARE}, "mirror": true}}}}}}"#
    );
    let mirrored = load(&node, "0").expect("loads");
    // Both face +z: the order was reversed to undo the scale's turn.
    assert_eq!(plain[0].plane(), Some(Vec4::new(0.0, 0.0, 1.0, 0.0)));
    assert_eq!(mirrored[0].plane(), Some(Vec4::new(0.0, 0.0, 1.0, 0.0)));
}

#[test]
fn nodes_without_the_convention_have_no_portal() {
    for extras in [
        r#""just a note""#,
        "42",
        r#"{"other": {"polygon": 1}}"#,
        "null",
    ] {
        let node = format!(r#"{{"extras": {extras}}}"#);
        assert_eq!(load(&node, "0").expect("loads"), Vec::new(), "{extras}");
    }
    // Portals on nodes outside the scene are not placed.
    let nodes = format!("{{}}, {}", portal_node(r#""mirror": true"#));
    assert_eq!(load(&nodes, "0").expect("loads"), Vec::new());
}

#[test]
fn malformed_declarations_are_clear_errors() {
    let ptr = "/nodes/0/extras/barytex_portal";
    let cases: Vec<(String, String, &str)> = vec![
        (r#"{"extras": {"barytex_portal": 7}}"#.into(), ptr.into(), "expected an object"),
        (
            r#"{"extras": {"barytex_portal": {"mirror": true}}}"#.into(),
            format!("{ptr}/polygon"),
            "'polygon' is missing",
        ),
        (
            r#"{"extras": {"barytex_portal": {"polygon": [[0, 0, 0], [1, 0, 0]], "mirror": true}}}"#
                .into(),
            format!("{ptr}/polygon"),
            "3 to 64 points",
        ),
        (
            format!(
                r#"{{"extras": {{"barytex_portal": {{"polygon": [{}], "mirror": true}}}}}}"#,
                vec!["[0, 0, 0]"; 65].join(", ")
            ),
            format!("{ptr}/polygon"),
            "3 to 64 points",
        ),
        (
            r#"{"extras": {"barytex_portal": {"polygon": [[0, 0, 0], [1, 0], [0, 1, 0]], "mirror": true}}}"#
                .into(),
            format!("{ptr}/polygon/1"),
            "3 numbers",
        ),
        (
            r#"{"extras": {"barytex_portal": {"polygon": [[0, 0, 0], [1, 0, 0], [0, 1e39, 0]], "mirror": true}}}"#
                .into(),
            format!("{ptr}/polygon/2/1"),
            "not a finite",
        ),
        (
            r#"{"extras": {"barytex_portal": {"polygon": [[0, 0, 0], [1, 0, 0], [0, "1", 0]], "mirror": true}}}"#
                .into(),
            format!("{ptr}/polygon/2/1"),
            "expected a number",
        ),
        (portal_node(""), ptr.into(), "\"mirror\": true or a \"target\""),
        (portal_node(r#""mirror": false"#), ptr.into(), "\"mirror\": true or a \"target\""),
        (portal_node(r#""mirror": true, "target": 0"#), format!("{ptr}/target"), "not both"),
        (portal_node(r#""target": 9"#), format!("{ptr}/target"), "node"),
        (portal_node(r#""mirror": 1"#), format!("{ptr}/mirror"), "a boolean"),
        (
            portal_node(r#""mirror": true, "tint": [0, 0, 1.5, 1]"#),
            format!("{ptr}/tint/2"),
            "[0, 1]",
        ),
        (portal_node(r#""mirror": true, "tint": [0, 0]"#), format!("{ptr}/tint"), "4 numbers"),
        (
            r#"{"extras": {"barytex_portal": {"polygon": [[0, 0, 0], [1, 0, 0], [2, 0, 0]], "mirror": true}}}"#
                .into(),
            ptr.into(),
            "no area",
        ),
        (
            r#"{"extras": {"barytex_portal": {"polygon": [[0, 0, 0], [2, 0, 0], [2, 2, 0], [1, 1, 0], [0, 2, 0]], "mirror": true}}}"#
                .into(),
            ptr.into(),
            "not convex",
        ),
        (
            format!(
                r#"{{"scale": [1, 0, 1], "extras": {{"barytex_portal": {{"polygon": {SQUARE}, "mirror": true}}}}}}"#
            ),
            ptr.into(),
            "no area",
        ),
    ];
    for (node, pointer, reason) in cases {
        let error = load(&node, "0").expect_err(&node);
        assert_eq!(error.pointer(), Some(pointer.as_str()), "{node}: {error}");
        let text = error.to_string();
        assert!(text.contains(reason), "{node}: {text}");
        // Values read from the file are never echoed.
        for value in ["1e39", "1.5", "\"1\"", "65"] {
            assert!(!text.contains(value), "{text}");
        }
    }
    // A singular target: its world matrix has no inverse.
    let nodes = format!(
        r#"{}, {{"scale": [0, 1, 1]}}"#,
        portal_node(r#""target": 1"#)
    );
    let error = load(&nodes, "0").expect_err("singular");
    assert!(error.to_string().contains("no inverse"), "{error}");
}

#[test]
fn the_portal_count_is_bounded() {
    let node = portal_node(r#""mirror": true"#);
    let nodes = [node.as_str(); 5].join(", ");
    let roots = "0, 1, 2, 3, 4";
    assert_eq!(load(&nodes, roots).expect("loads").len(), 5);
    let options = LoadOptions {
        limits: SceneLimits {
            max_portals: 4,
            ..SceneLimits::default()
        },
        ..LoadOptions::default()
    };
    let error = load_slice(document(&nodes, roots).as_bytes(), &options).expect_err("five");
    assert!(
        matches!(
            error,
            SceneError::TooLarge {
                what: "portals",
                requested: 5,
                limit: 4,
                ..
            }
        ),
        "{error}"
    );
    assert_eq!(error.pointer(), Some("/nodes/4"));
}
