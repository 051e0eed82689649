//! What the loader produces: materials, texture transforms, samplers, cameras, lights, world
//! matrices, mirrored instances, vertex colours of every component type.

mod common;

use barytex_gltf::{
    AlphaMode, LightKind, LoadOptions, MinFilter, Projection, Scene, Wrap, load_path, load_slice,
};
use base64::Engine as _;
use glam::{Mat3, Vec3, Vec4};

fn sample(name: &str, file: &str) -> Option<Scene> {
    let p = common::fixtures()?
        .join("gltf")
        .join(name)
        .join("glTF")
        .join(file);
    Some(load_path(&p, &LoadOptions::default()).unwrap_or_else(|e| panic!("{name}: {e}")))
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).abs().max_element() < 1e-5
}

#[test]
fn cameras_keep_their_parameters_and_placement() {
    let Some(s) = sample("Cameras", "Cameras.gltf") else {
        return;
    };
    let persp = s
        .cameras
        .iter()
        .find(|c| c.camera == 0)
        .map(|c| (c.projection, c.world));
    let Some((
        Projection::Perspective {
            yfov,
            aspect_ratio,
            znear,
            zfar,
        },
        world,
    )) = persp
    else {
        panic!("no perspective camera: {:?}", s.cameras);
    };
    assert!(
        (yfov - 0.7).abs() < 1e-6
            && aspect_ratio == Some(1.0)
            && znear == 0.01
            && zfar == Some(100.0)
    );
    assert!(close(
        world.transform_point3(Vec3::ZERO),
        Vec3::new(0.5, 0.5, 3.0)
    ));
    let ortho = s
        .cameras
        .iter()
        .find(|c| c.camera == 1)
        .map(|c| c.projection);
    assert_eq!(
        ortho,
        Some(Projection::Orthographic {
            xmag: 1.0,
            ymag: 1.0,
            znear: 0.01,
            zfar: 100.0
        })
    );
}

#[test]
fn texture_transforms_become_matrices() {
    let Some(s) = sample("TextureTransformTest", "TextureTransformTest.gltf") else {
        return;
    };
    let by_name = |n: &str| {
        s.materials
            .iter()
            .find(|m| m.name.as_deref() == Some(n))
            .and_then(|m| m.base_color_texture)
            .map(|t| t.mapping.transform)
            .unwrap_or_else(|| panic!("material {n}"))
    };
    let offset_u = by_name("Offset U");
    assert!(close(
        offset_u * Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(0.5, 0.0, 1.0)
    ));
    let scale = by_name("Scale");
    assert!(close(
        scale * Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(1.5, 1.5, 1.0)
    ));
    let rotation = by_name("Rotation");
    let r = std::f32::consts::FRAC_PI_8; // the file's 0.39269908169872414
    assert!(close(rotation * Vec3::X, Vec3::new(r.cos(), -r.sin(), 0.0)));
    assert_ne!(by_name("All"), Mat3::IDENTITY);
    assert!(s.stats.images_decoded > 0);
}

#[test]
fn samplers_map_the_gl_enums() {
    let Some(s) = sample("TextureSettingsTest", "TextureSettingsTest.gltf") else {
        return;
    };
    let samplers: Vec<_> = s.textures.iter().map(|t| t.sampler).collect();
    assert!(
        samplers
            .iter()
            .all(|x| x.min_filter == MinFilter::NearestMipmapLinear)
    );
    assert!(
        samplers
            .iter()
            .any(|x| x.wrap_s == Wrap::Repeat && x.wrap_t == Wrap::ClampToEdge)
    );
    assert!(
        samplers
            .iter()
            .any(|x| x.wrap_s == Wrap::MirroredRepeat && x.wrap_t == Wrap::Repeat)
    );
    let d = samplers
        .iter()
        .find(|x| x.wrap_t == Wrap::MirroredRepeat)
        .map(barytex_gltf::SamplerParams::to_descriptor);
    assert!(matches!(
        d,
        Some(d) if d.address_mode_v == barytex_texture::sampler::AddressMode::MirrorRepeat
    ));
}

#[test]
fn unlit_and_colour_spaces() {
    if let Some(s) = sample("UnlitTest", "UnlitTest.gltf") {
        assert!(s.materials.iter().all(|m| m.unlit));
    }
    if let Some(s) = sample("Avocado", "Avocado.gltf") {
        let m = &s.materials[0];
        let base = m
            .base_color_texture
            .and_then(|t| t.image)
            .unwrap_or(usize::MAX);
        let normal = m.normal_texture.and_then(|t| t.image).unwrap_or(usize::MAX);
        assert!(s.images[base].srgb.is_some() && s.images[base].linear.is_none());
        assert!(s.images[normal].linear.is_some() && s.images[normal].srgb.is_none());
    }
}

/// A glTF whose one buffer is `data` (base64 data URI), with the rest of the JSON given.
fn with_buffer(data: &[u8], rest: &str) -> String {
    let b64 = base64::engine::general_purpose::STANDARD.encode(data);
    format!(
        r#"{{"asset":{{"version":"2.0"}},
            "buffers":[{{"byteLength":{},"uri":"data:application/octet-stream;base64,{b64}"}}],
            {rest}}}"#,
        data.len()
    )
}

fn floats(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|f| f.to_le_bytes()).collect()
}

#[test]
fn mirrored_instances_flip_winding_and_colours_of_every_type() {
    // Positions (36 bytes), then u8-normalised RGB colours padded to 4 bytes per vertex (12),
    // then u16-normalised RGBA (24).
    let mut data = floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    data.extend_from_slice(&[255, 0, 0, 0, 0, 255, 0, 0, 0, 0, 255, 0]);
    for c in [[65535u16, 0, 0, 65535], [0, 32768, 0, 0], [0, 0, 0, 65535]] {
        for x in c {
            data.extend_from_slice(&x.to_le_bytes());
        }
    }
    let gltf = with_buffer(
        &data,
        r#""bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":12,"byteStride":4},
                          {"buffer":0,"byteOffset":48,"byteLength":24}],
           "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                        {"bufferView":1,"componentType":5121,"normalized":true,"count":3,"type":"VEC3"},
                        {"bufferView":2,"componentType":5123,"normalized":true,"count":3,"type":"VEC4"}],
           "materials":[{"alphaMode":"MASK","doubleSided":true}],
           "meshes":[{"primitives":[{"attributes":{"POSITION":0,"COLOR_0":1},"material":0}]},
                     {"primitives":[{"attributes":{"POSITION":0,"COLOR_0":2}}]}],
           "nodes":[{"children":[1,2],"translation":[10,0,0]},
                    {"mesh":0,"scale":[-1,1,1]},
                    {"mesh":1,"rotation":[0,0,0.7071068,0.7071068]}],
           "scenes":[{"nodes":[0]}]"#,
    );
    let s = load_slice(gltf.as_bytes(), &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.instances.len(), 2);
    let mirrored = &s.instances[0];
    assert!(mirrored.flips_winding);
    assert!(close(
        mirrored.world.transform_point3(Vec3::X),
        Vec3::new(9.0, 0.0, 0.0)
    ));
    let rgb = mirrored.mesh.primitives[0]
        .colors0
        .clone()
        .unwrap_or_default();
    assert_eq!(
        rgb,
        vec![
            Vec4::new(1.0, 0.0, 0.0, 1.0),
            Vec4::new(0.0, 1.0, 0.0, 1.0),
            Vec4::new(0.0, 0.0, 1.0, 1.0)
        ]
    );
    let rotated = &s.instances[1];
    assert!(!rotated.flips_winding);
    assert!(close(
        rotated.world.transform_point3(Vec3::X),
        Vec3::new(10.0, 1.0, 0.0)
    ));
    let rgba = rotated.mesh.primitives[0]
        .colors0
        .clone()
        .unwrap_or_default();
    assert_eq!(rgba[0], Vec4::new(1.0, 0.0, 0.0, 1.0));
    assert!((rgba[1].y - 32768.0 / 65535.0).abs() < 1e-7);
    let m = s.material(Some(0));
    assert_eq!(m.alpha_mode, AlphaMode::Mask { cutoff: 0.5 });
    assert!(m.double_sided);
    assert_eq!(s.material(None).base_color_factor, Vec4::ONE);
}

#[test]
fn lights_are_placed() {
    let gltf = r#"{"asset":{"version":"2.0"},"extensionsUsed":["KHR_lights_punctual"],
        "extensions":{"KHR_lights_punctual":{"lights":[
            {"type":"spot","color":[1,0.5,0],"intensity":20,"range":5,"spot":{"innerConeAngle":0.1,"outerConeAngle":0.5}},
            {"type":"directional"}]}},
        "nodes":[{"translation":[1,2,3],"extensions":{"KHR_lights_punctual":{"light":0}}},
                 {"rotation":[-0.7071068,0,0,0.7071068],"extensions":{"KHR_lights_punctual":{"light":1}}}],
        "scenes":[{"nodes":[0,1]}]}"#;
    let s = load_slice(gltf.as_bytes(), &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.lights.len(), 2);
    let spot = &s.lights[0];
    assert_eq!(
        spot.light.kind,
        LightKind::Spot {
            inner_cone_angle: 0.1,
            outer_cone_angle: 0.5
        }
    );
    assert_eq!((spot.light.intensity, spot.light.range), (20.0, Some(5.0)));
    assert!(close(spot.position, Vec3::new(1.0, 2.0, 3.0)) && close(spot.direction, Vec3::NEG_Z));
    // Rotated −90° about X, −Z turns to −Y: the sun shines straight down.
    assert!(
        close(s.lights[1].direction, Vec3::NEG_Y),
        "{:?}",
        s.lights[1].direction
    );
    assert_eq!(s.lights[1].light.color, Vec3::ONE);
}

#[test]
fn strips_keep_their_orientation() {
    // A quad as a 4-vertex strip: both triangles must face +Z (counter-clockwise).
    let data = floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0]);
    let gltf = with_buffer(
        &data,
        r#""bufferViews":[{"buffer":0,"byteLength":48}],
           "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
           "meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":5}]}],
           "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]"#,
    );
    let s = load_slice(gltf.as_bytes(), &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let p = &s.instances[0].mesh.primitives[0];
    for t in &p.triangles {
        let [a, b, c] = t.map(|i| p.positions[i as usize]);
        assert!((b - a).cross(c - a).z > 0.0, "{t:?} faces away");
    }
    assert_eq!(p.triangles.len(), 2);
}

/// glTF 2.0 §3.6.2.4 "Data Alignment": a matrix column whose `rows × component size` is not a
/// multiple of 4 (MAT2 of 1-byte, MAT3 of 1- or 2-byte components) is padded to a 4-byte
/// boundary. The padding separates columns and elements; the last element of an accessor needs
/// only its real bytes, so a bufferView may end right after the last column's data (the
/// glTF-Validator's element length: 6 for MAT2 u8, 11 for MAT3 u8, 22 for MAT3 u16).
#[test]
fn padded_matrix_accessors_end_at_their_last_real_byte() {
    // Two elements each: MAT2 i8 in 8 + 6 = 14 bytes, MAT3 u8 in 12 + 11 = 23 bytes,
    // MAT3 u16 in 24 + 22 = 46 bytes (the views start at 4-byte-aligned offsets 0, 16, 40).
    let mut data = vec![0u8; 86];
    data[0] = 1; // element 0, column 0, row 0 of the MAT2
    data[12] = 0xFE; // element 1, column 1, row 0 of the MAT2: -2
    data[16 + 12 + 8 + 2] = 9; // MAT3 u8: element 1, column 2, row 2 (the view's last byte)
    data[40 + 24 + 16 + 4] = 7; // MAT3 u16: element 1, column 2, row 2 (the view's last two)
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0"}},
            "buffers":[{{"byteLength":86,"uri":"data:application/octet-stream;base64,{}"}}],
            "bufferViews":[{{"buffer":0,"byteLength":14}},
                           {{"buffer":0,"byteOffset":16,"byteLength":23}},
                           {{"buffer":0,"byteOffset":40,"byteLength":46}}],
            "accessors":[{{"bufferView":0,"componentType":5120,"count":2,"type":"MAT2",
                           "min":[0,0,-2,0],"max":[1,0,0,0]}},
                         {{"bufferView":1,"componentType":5121,"count":2,"type":"MAT3",
                           "min":[0,0,0,0,0,0,0,0,0],"max":[0,0,0,0,0,0,0,0,9]}},
                         {{"bufferView":2,"componentType":5123,"count":2,"type":"MAT3",
                           "min":[0,0,0,0,0,0,0,0,0],"max":[0,0,0,0,0,0,0,0,7]}}]}}"#,
        base64::engine::general_purpose::STANDARD.encode(&data)
    );
    let r = load_slice(gltf.as_bytes(), &LoadOptions::default());
    assert!(r.is_ok(), "{r:?}");
    // One byte less than the real bytes is still refused, naming the accessor.
    for (view, len) in [(0, 14), (1, 23), (2, 46)] {
        let short = gltf.replacen(
            &format!(r#""byteLength":{len}}}"#),
            &format!(r#""byteLength":{}}}"#, len - 1),
            1,
        );
        assert_ne!(short, gltf);
        let r = load_slice(short.as_bytes(), &LoadOptions::default());
        assert!(
            matches!(&r, Err(barytex_gltf::SceneError::Invalid { pointer, .. })
                if *pointer == format!("/accessors/{view}")),
            "view {view} at {} bytes: {r:?}",
            len - 1
        );
    }
    // The validator's own test asset for these elements loads too (when the fixtures exist).
    if let Some(root) = common::fixtures() {
        let p = root.join(
            "gltf-invalid/glTF-Validator/test/base/data/accessor_data/get_elements_matrix.gltf",
        );
        if p.exists() {
            let r = load_path(&p, &LoadOptions::default());
            assert!(r.is_ok(), "{r:?}");
        }
    }
}
