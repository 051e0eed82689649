//! `barytex uv-layout FILE`: the uv layout of every textured primitive of a glTF scene, drawn
//! over the texture its material samples.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use barytex_gltf::{LoadOptions, Material, Primitive, Scene, TextureRef, load_path};
use barytex_texture::load::{AnyTexture2d, ColorSpace};
use barytex_uv::distortion::MeshDistortion;
use barytex_uv::layout::{LayoutOptions, draw_uv_layout, write_png};
use barytex_uv::mesh::TriMesh;
use glam::Vec2;
use tiny_skia::{ColorU8, Pixmap};

/// One picture to draw: a primitive's uvs in the set its texture reads, with that texture.
struct Layout<'a> {
    /// File name (without the folder).
    name: String,
    /// The primitive's positions, the uvs (after the texture transform) and triangles.
    mesh: TriMesh,
    /// The texture drawn under the wireframe and how it is described; `None`: a checker.
    texture: Option<(&'a AnyTexture2d, ColorSpace, String)>,
}

/// Keeps letters, digits, `-` and `_` of a glTF name (others become `_`), at most 40 of them.
fn file_safe(name: &str) -> String {
    name.chars()
        .take(40)
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// The texture whose layout matters most: the base colour texture, else the first other one.
fn main_texture(material: &Material) -> Option<(TextureRef, ColorSpace)> {
    material.texture_refs().into_iter().next()
}

/// The uvs `texture` reads on `primitive` (its `texCoord` set, through its texture transform);
/// `TEXCOORD_0` when the material has no texture.
fn primitive_uvs(primitive: &Primitive, texture: Option<&TextureRef>) -> Option<Vec<Vec2>> {
    let set = texture.map_or(0, |t| t.mapping.set);
    let uvs = match set {
        0 => primitive.tex_coords0.as_ref(),
        1 => primitive.tex_coords1.as_ref(),
        _ => None,
    }?;
    Some(match texture {
        Some(t) => uvs
            .iter()
            .map(|&uv| t.mapping.transform.transform_point2(uv))
            .collect(),
        None => uvs.clone(),
    })
}

/// Every textured primitive of the scene's meshes (each mesh once, however often instanced).
fn layouts(scene: &Scene) -> Vec<Layout<'_>> {
    let mut seen = HashSet::new();
    let mut result = Vec::new();
    for instance in &scene.instances {
        let mesh = &instance.mesh;
        if !seen.insert(mesh.index) {
            continue;
        }
        let mesh_name = mesh
            .name
            .as_deref()
            .map(|n| format!("-{}", file_safe(n)))
            .unwrap_or_default();
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            // Points and lines have no area to lay out.
            if !primitive.topology.is_triangles() {
                continue;
            }
            let material = scene.material(primitive.material);
            let texture_ref = main_texture(&material);
            let Some(uvs) = primitive_uvs(primitive, texture_ref.as_ref().map(|(t, _)| t)) else {
                continue;
            };
            let texture = texture_ref.and_then(|(t, space)| {
                let image = scene.images.get(t.image?)?;
                let decoded = match space {
                    ColorSpace::Srgb => image.srgb.as_deref(),
                    ColorSpace::Linear => image.linear.as_deref(),
                }?;
                let described = image
                    .name
                    .clone()
                    .unwrap_or_else(|| format!("image {}", t.image.unwrap_or_default()));
                Some((decoded, space, described))
            });
            result.push(Layout {
                name: format!("mesh{}{mesh_name}-primitive{p}.png", mesh.index),
                mesh: TriMesh {
                    positions: primitive.positions.clone(),
                    uvs,
                    indices: primitive.triangles.clone(),
                    ..TriMesh::default()
                },
                texture,
            });
        }
    }
    result
}

/// `texture` as an opaque 8-bit picture: colour textures sRGB-encoded, data textures as stored.
fn to_pixmap(texture: &AnyTexture2d, space: ColorSpace) -> Result<Pixmap, String> {
    let linear = texture.to_rgba32f().map_err(|e| e.to_string())?;
    let (w, h) = linear.size();
    let mut pixmap = Pixmap::new(w, h).ok_or("texture too large to draw")?;
    let byte = |v: f32| match space {
        ColorSpace::Srgb => barytex_texture::srgb::encode(v),
        // Saturating float-to-int casts: NaN gives 0.
        ColorSpace::Linear => (v.clamp(0.0, 1.0) * 255.0).round() as u8,
    };
    for (pixel, texel) in pixmap.pixels_mut().iter_mut().zip(linear.texels()) {
        let [r, g, b, _] = texel.0;
        *pixel = ColorU8::from_rgba(byte(r), byte(g), byte(b), 255).premultiply();
    }
    Ok(pixmap)
}

/// The smallest box holding every finite uv.
fn uv_range(uvs: &[Vec2]) -> Option<(Vec2, Vec2)> {
    let finite = uvs.iter().filter(|uv| uv.is_finite());
    let lo = finite.clone().copied().reduce(Vec2::min)?;
    let hi = finite.copied().reduce(Vec2::max)?;
    Some((lo, hi))
}

/// Draws every textured primitive of `file`'s scene into `out` (a folder, created if missing) and
/// prints each picture's path, texture, uv range and distortion.
pub(crate) fn run_file(
    file: &Path,
    scene: Option<usize>,
    allowed_roots: &[PathBuf],
    size: u32,
    out: Option<PathBuf>,
) -> Result<(), Box<dyn std::error::Error>> {
    let loaded = load_path(
        file,
        &LoadOptions {
            scene,
            allowed_roots: allowed_roots.to_vec(),
            ..LoadOptions::default()
        },
    )
    .map_err(|e| format!("{}: {e}", file.display()))?;
    let out = out.unwrap_or_else(|| {
        let stem = file
            .file_stem()
            .map_or_else(|| "scene".to_owned(), |s| file_safe(&s.to_string_lossy()));
        PathBuf::from(format!("{stem}-uv-layout"))
    });
    let layouts = layouts(&loaded);
    if layouts.is_empty() {
        return Err(format!(
            "{}: no primitive of the scene has texture coordinates",
            file.display()
        )
        .into());
    }
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    for layout in &layouts {
        let background = layout
            .texture
            .as_ref()
            .map(|(t, space, _)| to_pixmap(t, *space))
            .transpose()?;
        let options = LayoutOptions {
            texture: background.as_ref(),
            ..LayoutOptions::default()
        };
        let picture = draw_uv_layout(&layout.mesh, size, &options)?;
        let path = out.join(&layout.name);
        write_png(&picture, &path)?;
        let over = layout
            .texture
            .as_ref()
            .map_or_else(|| "a checker".to_owned(), |(_, _, name)| name.clone());
        println!(
            "wrote {} ({} triangles over {over})",
            path.display(),
            layout.mesh.indices.len()
        );
        if let Some((lo, hi)) = uv_range(&layout.mesh.uvs) {
            let outside = lo.min_element() < 0.0 || hi.max_element() > 1.0;
            println!(
                "  uv range [{:.3}, {:.3}] × [{:.3}, {:.3}]{}",
                lo.x,
                hi.x,
                lo.y,
                hi.y,
                if outside {
                    " (beyond the unit square: those edges are clipped)"
                } else {
                    ""
                }
            );
        }
        if let Some(d) = MeshDistortion::of(&layout.mesh) {
            println!(
                "  distortion (area-weighted mean / max): area {:.4} / {:.2}, angle {:.3} / {:.2}",
                d.area_mean, d.area_max, d.angle_mean, d.angle_max
            );
        }
    }
    Ok(())
}
