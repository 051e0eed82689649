//! `barytex unwrap`: new texture coordinates for every triangle primitive of a glTF model (or a
//! built-in mesh), packed into the unit square, checked exactly, written as a new uv set with a
//! picture of the layout.
//!
//! Each mesh of the scene is unwrapped once (its instances share it), all its triangle
//! primitives together in one unit square, in object space: the texel density is uniform over
//! the mesh. Positions are welded first, so charts may cross the seams where a glTF splits
//! vertices (normals, old uvs); in the output each primitive's vertices are split again where
//! a chart boundary runs, and every attribute follows its vertex.

mod gltf_write;
mod measure;
mod uri;
mod weld;

use crate::progress::Progress;
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::time::Instant;

use barytex_gltf::{LoadOptions, Primitive, Topology, load_path};
use barytex_unwrap::pack::PackOptions;
use barytex_unwrap::{Atlas, ChartMethod, Method, ParamOptions, UnwrapOptions, unwrap};
use barytex_uv::layout::{LayoutOptions, draw_uv_layout, write_png};
use barytex_uv::mesh::TriMesh;
use clap::ValueEnum;
use glam::{DVec2, Vec2, Vec3, Vec4};
use serde_json::{Value, json};

use crate::uv_layout::MeshKind;
use gltf_write::{CARRIED, NewPrimitive};
use measure::{LayoutStats, measure};

/// How charts are made (`--method`).
#[derive(Clone, Copy, Debug, ValueEnum)]
pub(crate) enum MethodArg {
    /// Segmentation, least squares conformal maps, then as-rigid-as-possible refinement.
    LscmArap,
    /// Segmentation and least squares conformal maps.
    Lscm,
    /// Segmentation and Floater's mean-value embedding onto a circle.
    MeanValue,
    /// Segmentation and Tutte's uniform embedding onto a circle.
    Tutte,
    /// Segmentation and the harmonic (cotangent) embedding onto a circle.
    Harmonic,
    /// Two triangles sharing an edge per chart, unfolded flat without distortion.
    Pairs,
    /// One chart per triangle, flat without distortion (lightmaps).
    PerTriangle,
}

impl MethodArg {
    /// The library's options for this method, with `base` for the parameterizing methods (its
    /// own method replaced).
    fn options(self, base: &ParamOptions, pack: PackOptions) -> UnwrapOptions {
        let param = |method| UnwrapOptions {
            charts: ChartMethod::Parameterize,
            param: ParamOptions {
                method,
                ..base.clone()
            },
            pack,
        };
        match self {
            Self::LscmArap => param(Method::LscmArap),
            Self::Lscm => param(Method::Lscm),
            Self::MeanValue => param(Method::MeanValue),
            Self::Tutte => param(Method::Tutte),
            Self::Harmonic => param(Method::Harmonic),
            Self::Pairs => UnwrapOptions {
                charts: ChartMethod::TrianglePairs,
                pack,
                ..UnwrapOptions::default()
            },
            Self::PerTriangle => UnwrapOptions {
                charts: ChartMethod::PerTriangle,
                pack,
                ..UnwrapOptions::default()
            },
        }
    }
}

/// Parses `--cone`: degrees in `(0, 180]`.
pub(crate) fn parse_cone(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(d) if d > 0.0 && d <= 180.0 => Ok(d),
        _ => Err("expected degrees above 0 and at most 180".to_owned()),
    }
}

/// Parses a distortion limit: a ratio of at least 1 (infinity allowed: never split).
pub(crate) fn parse_ratio(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(r) if r >= 1.0 => Ok(r),
        _ => {
            Err("expected a ratio of at least 1 (1 is no distortion; inf never splits)".to_owned())
        }
    }
}

/// Where the mesh comes from.
pub(crate) enum Source {
    /// A glTF or GLB file.
    File {
        /// The file.
        path: PathBuf,
        /// Which of its scenes.
        scene: Option<usize>,
        /// Folders besides its own that its URIs may read.
        allowed_roots: Vec<PathBuf>,
    },
    /// A built-in parametric mesh (its own uvs are ignored).
    Mesh(MeshKind),
}

/// What `unwrap` was asked for.
pub(crate) struct Options {
    pub(crate) source: Source,
    /// The `.gltf` to write (files only).
    pub(crate) out: Option<PathBuf>,
    /// `TEXCOORD_<n>` to write; `None`: 1 when every primitive has `TEXCOORD_0`, else 0.
    pub(crate) uv_set: Option<u32>,
    pub(crate) method: MethodArg,
    /// Segmentation and distortion options (their `method` is `method`'s).
    pub(crate) param: ParamOptions,
    pub(crate) pack: PackOptions,
    /// The layout picture (default `<out stem>-uv-layout.png`).
    pub(crate) layout: Option<PathBuf>,
    pub(crate) stats: bool,
    /// Writes the figures as JSON here.
    pub(crate) stats_json: Option<PathBuf>,
    /// Writes the welded mesh (what is unwrapped) as JSON here, for peers.
    pub(crate) dump_mesh: Option<PathBuf>,
    /// Measures a peer's uvs of the dumped mesh (see `tools/xatlas_unwrap.py`).
    pub(crate) compare_uvs: Option<PathBuf>,
}

/// One mesh to unwrap: its triangle primitives, with where each sits in the JSON.
struct Unit<'a> {
    /// Index into the document's `meshes` (none for a built-in mesh).
    mesh: usize,
    /// `(JSON primitive index, decoded primitive)`.
    primitives: Vec<(usize, &'a Primitive)>,
}

/// The largest layout picture side (pixels).
const MAX_LAYOUT_PICTURE: u32 = 2048;

/// A file's bytes, read as the loader reads its files (a regular file of at most `limit` bytes,
/// opened without waiting on a FIFO).
fn read_bounded(path: &Path, limit: u64) -> Result<Vec<u8>, String> {
    barytex_gltf::read_regular_file(path, limit).map_err(|e| format!("{}: {e}", path.display()))
}

fn built_in(kind: MeshKind) -> Result<Primitive, String> {
    let m = kind.build().map_err(|e| e.to_string())?;
    Ok(Primitive {
        positions: m.positions,
        normals: Some(m.normals),
        tangents: Some(m.tangents),
        tex_coords0: Some(m.uvs),
        tex_coords1: None,
        colors0: None,
        triangles: m.indices,
        indices: Vec::new(),
        material: None,
        topology: Topology::Triangles,
    })
}

/// The JSON primitives that barytex-gltf decodes (a known mode and a `POSITION`), in order.
fn decoded_json_primitives(doc: &Value, mesh: usize) -> Vec<usize> {
    doc["meshes"][mesh]["primitives"]
        .as_array()
        .map(|list| {
            list.iter()
                .enumerate()
                .filter(|(_, p)| {
                    let mode = p.get("mode").and_then(Value::as_u64).unwrap_or(4);
                    Topology::from_gl(mode).is_some()
                        && p.get("attributes")
                            .and_then(|a| a.get("POSITION"))
                            .is_some()
                })
                .map(|(i, _)| i)
                .collect()
        })
        .unwrap_or_default()
}

/// The uv set to write, checked against every primitive: glTF's `TEXCOORD_n` sets are numbered
/// from 0 without gaps (glTF 2.0 §3.7.2.1), so set `n` needs sets `0..n` there already.
fn choose_uv_set(doc: &Value, units: &[Unit<'_>], asked: Option<u32>) -> Result<u32, String> {
    let sets_of = |unit: &Unit<'_>, p: usize| -> u32 {
        let attributes = &doc["meshes"][unit.mesh]["primitives"][p]["attributes"];
        (0..8)
            .take_while(|n| attributes.get(format!("TEXCOORD_{n}")).is_some())
            .count() as u32
    };
    let fewest = units
        .iter()
        .flat_map(|u| u.primitives.iter().map(move |&(p, _)| sets_of(u, p)))
        .min()
        .unwrap_or(0);
    match asked {
        None => Ok(fewest.min(1)),
        Some(n) if n <= fewest => Ok(n),
        Some(n) => Err(format!(
            "--uv-set {n}: glTF numbers uv sets without gaps, and a primitive has only {fewest} \
             (use --uv-set {fewest} or lower)"
        )),
    }
}

/// Refuses primitives whose data unwrap cannot carry into split vertices.
fn check_carried(doc: &Value, unit: &Unit<'_>) -> Result<(), String> {
    for &(p, _) in &unit.primitives {
        let json = &doc["meshes"][unit.mesh]["primitives"][p];
        let at = format!("/meshes/{}/primitives/{p}", unit.mesh);
        if json.get("targets").is_some() {
            return Err(format!(
                "{at}: morph targets cannot be carried over yet; nothing was written"
            ));
        }
        if let Some(names) = json.get("attributes").and_then(Value::as_object)
            && let Some(other) = names.keys().find(|k| !CARRIED.contains(&k.as_str()))
        {
            return Err(format!(
                "{at}: attribute {other} cannot be carried over yet (unwrap rewrites {}); \
                 nothing was written",
                CARRIED.join(", ")
            ));
        }
    }
    Ok(())
}

/// A layout as flat lists: each uv vertex's position and glTF uv, and the triangles.
type FlatLayout = (Vec<Vec3>, Vec<DVec2>, Vec<[u32; 3]>);

/// What one unwrapped mesh gives.
struct Unwrapped<'a> {
    welded: weld::Welded,
    atlas: Atlas,
    new_primitives: Vec<NewPrimitive<'a>>,
    /// The layout as a flat list.
    layout: FlatLayout,
    seconds_weld: f64,
}

fn unwrap_unit<'a>(unit: &Unit<'a>, options: &UnwrapOptions) -> Result<Unwrapped<'a>, String> {
    let started = Instant::now();
    let sources: Vec<&Primitive> = unit.primitives.iter().map(|&(_, p)| p).collect();
    let welded = weld::weld(&sources)?;
    let seconds_weld = started.elapsed().as_secs_f64();
    let atlas = unwrap(&welded.mesh, options).map_err(|e| e.to_string())?;
    // New vertices per primitive: one per (chart, chart vertex, old vertex).
    let mut keys: Vec<HashMap<(u32, u32, u32), u32>> = vec![HashMap::new(); sources.len()];
    let mut new: Vec<NewPrimitive<'a>> = unit
        .primitives
        .iter()
        .map(|&(primitive, source)| NewPrimitive {
            mesh: unit.mesh,
            primitive,
            source,
            vertex_of: Vec::new(),
            uvs: Vec::new(),
            triangles: Vec::new(),
        })
        .collect();
    let mut flat_positions = Vec::new();
    let mut flat_uvs = Vec::new();
    let mut flat_triangles = Vec::new();
    let positions = welded.mesh.positions();
    for (c, chart) in atlas.charts.iter().enumerate() {
        let base = flat_positions.len() as u32;
        for (&v, uv) in chart.vertices.iter().zip(&chart.uvs) {
            flat_positions.push(positions[v as usize].as_vec3());
            flat_uvs.push(DVec2::new(uv.x, 1.0 - uv.y));
        }
        for (j, t) in chart.triangles.iter().enumerate() {
            flat_triangles.push(t.map(|i| base + i));
            let (slot, tri) = welded.source[chart.faces[j] as usize];
            let old = sources[slot as usize].triangles[tri as usize];
            let target = &mut new[slot as usize];
            let mut corners = [0u32; 3];
            for k in 0..3 {
                let key = (c as u32, t[k], old[k]);
                let next = target.vertex_of.len() as u32;
                corners[k] = *keys[slot as usize].entry(key).or_insert_with(|| {
                    let uv = chart.uvs[t[k] as usize];
                    target.vertex_of.push(old[k]);
                    target.uvs.push(Vec2::new(uv.x as f32, (1.0 - uv.y) as f32));
                    next
                });
            }
            target.triangles.push(corners);
        }
    }
    Ok(Unwrapped {
        welded,
        atlas,
        new_primitives: new,
        layout: (flat_positions, flat_uvs, flat_triangles),
        seconds_weld,
    })
}

/// A peer's uvs for the dumped mesh: `{"vertex_of": [..], "uvs": [[u, v], ..], "indices":
/// [[a, b, c], ..]}`, each uv vertex naming a vertex of the dumped (welded) mesh.
fn read_peer_uvs(path: &Path, positions: &[glam::DVec3]) -> Result<FlatLayout, String> {
    let bytes = read_bounded(path, 1 << 30)?;
    let doc: Value =
        serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
    let bad = |what: &str| format!("{}: {what}", path.display());
    let list = |key: &str| {
        doc.get(key)
            .and_then(Value::as_array)
            .ok_or_else(|| bad(&format!("no `{key}` list")))
    };
    let vertex_of: Vec<u32> = list("vertex_of")?
        .iter()
        .map(|v| v.as_u64().and_then(|v| u32::try_from(v).ok()))
        .collect::<Option<_>>()
        .ok_or_else(|| bad("`vertex_of` must hold vertex indices"))?;
    let uvs: Vec<DVec2> = list("uvs")?
        .iter()
        .map(|p| Some(DVec2::new(p.get(0)?.as_f64()?, p.get(1)?.as_f64()?)))
        .collect::<Option<_>>()
        .ok_or_else(|| bad("`uvs` must hold [u, v] pairs"))?;
    let indices: Vec<[u32; 3]> = list("indices")?
        .iter()
        .map(|t| {
            let i = |k: usize| t.get(k)?.as_u64().and_then(|v| u32::try_from(v).ok());
            Some([i(0)?, i(1)?, i(2)?])
        })
        .collect::<Option<_>>()
        .ok_or_else(|| bad("`indices` must hold [a, b, c] triangles"))?;
    if vertex_of.len() != uvs.len() {
        return Err(bad("`vertex_of` and `uvs` differ in length"));
    }
    let points = vertex_of
        .iter()
        .map(|&v| positions.get(v as usize).map(|p| p.as_vec3()))
        .collect::<Option<Vec<Vec3>>>()
        .ok_or_else(|| bad("`vertex_of` names a vertex the mesh does not have"))?;
    Ok((points, uvs, indices))
}

fn write_json(path: &Path, value: &Value) -> Result<(), String> {
    let text = serde_json::to_string_pretty(value).map_err(|e| e.to_string())?;
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

fn absolute_dir(path: &Path) -> Result<PathBuf, String> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or_else(|| Path::new("."));
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    std::fs::canonicalize(dir).map_err(|e| format!("{}: {e}", dir.display()))
}

/// Runs `barytex unwrap`.
pub(crate) fn run(options: &Options) -> Result<(), Box<dyn std::error::Error>> {
    let progress = Progress::start();
    let started = Instant::now();
    let mut times: BTreeMap<&'static str, f64> = BTreeMap::new();
    let unwrap_options = options.method.options(&options.param, options.pack);
    options
        .pack
        .validate()
        .map_err(|e| format!("--size/--padding: {e}"))?;
    // Load.
    progress.stage("loading");
    let built;
    let scene;
    let mut doc = Value::Null;
    let mut glb_bin: Option<Vec<u8>> = None;
    let (units, name): (Vec<Unit<'_>>, String) = match &options.source {
        Source::Mesh(kind) => {
            built = built_in(*kind)?;
            (
                vec![Unit {
                    mesh: 0,
                    primitives: vec![(0, &built)],
                }],
                kind.name().to_owned(),
            )
        }
        Source::File {
            path,
            scene: which,
            allowed_roots,
        } => {
            let load_options = LoadOptions {
                scene: *which,
                allowed_roots: allowed_roots.clone(),
                decode_images: false,
                ..LoadOptions::default()
            };
            scene =
                load_path(path, &load_options).map_err(|e| format!("{}: {e}", path.display()))?;
            let bytes = read_bounded(path, load_options.limits.max_file_bytes)?;
            let json_bytes = if bytes.starts_with(b"glTF") {
                let (json, bin) = barytex_gltf::glb_chunks(&bytes)
                    .map_err(|e| format!("{}: {e}", path.display()))?;
                glb_bin = bin.map(<[u8]>::to_vec);
                json.to_vec()
            } else {
                bytes
            };
            doc = serde_json::from_slice(&json_bytes)
                .map_err(|e| format!("{}: JSON: {e}", path.display()))?;
            let mut seen = std::collections::BTreeSet::new();
            let mut units = Vec::new();
            for instance in &scene.instances {
                let mesh = &instance.mesh;
                if !seen.insert(mesh.index) {
                    continue;
                }
                let json_primitives = decoded_json_primitives(&doc, mesh.index);
                if json_primitives.len() != mesh.primitives.len() {
                    return Err(format!(
                        "{}: mesh {} decodes to {} primitives but declares {} (please report)",
                        path.display(),
                        mesh.index,
                        mesh.primitives.len(),
                        json_primitives.len()
                    )
                    .into());
                }
                let primitives: Vec<(usize, &Primitive)> = json_primitives
                    .into_iter()
                    .zip(&mesh.primitives)
                    .filter(|(_, p)| p.topology.is_triangles() && !p.triangles.is_empty())
                    .collect();
                if !primitives.is_empty() {
                    units.push(Unit {
                        mesh: mesh.index,
                        primitives,
                    });
                }
            }
            let stem = path
                .file_stem()
                .map_or_else(|| "model".into(), |s| s.to_string_lossy().into_owned());
            (units, stem)
        }
    };
    times.insert("load", started.elapsed().as_secs_f64());
    if units.is_empty() {
        return Err("nothing to unwrap: the scene has no triangles".into());
    }
    let is_file = matches!(options.source, Source::File { .. });
    let uv_set = if is_file {
        for unit in &units {
            check_carried(&doc, unit)?;
        }
        choose_uv_set(&doc, &units, options.uv_set)?
    } else {
        0
    };
    if (options.dump_mesh.is_some() || options.compare_uvs.is_some()) && units.len() != 1 {
        return Err(format!(
            "--dump-mesh and --compare-uvs take a model with one mesh; this scene has {}",
            units.len()
        )
        .into());
    }
    let out = match (&options.source, &options.out) {
        (Source::File { .. }, Some(out)) => Some(out.clone()),
        (Source::File { .. }, None) => Some(PathBuf::from(format!("{name}-unwrapped.gltf"))),
        (Source::Mesh(_), _) => None,
    };
    if let Some(out) = &out
        && out
            .extension()
            .is_none_or(|e| !(e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb")))
    {
        return Err(format!(
            "{}: unwrap writes .gltf (JSON and a .bin) or .glb",
            out.display()
        )
        .into());
    }
    // Unwrap each mesh.
    let mut results = Vec::with_capacity(units.len());
    for (k, unit) in units.iter().enumerate() {
        let triangles: usize = unit.primitives.iter().map(|(_, p)| p.triangles.len()).sum();
        progress.stage(format!(
            "unwrapping mesh {}/{} ({triangles} triangles)",
            k + 1,
            units.len()
        ));
        results.push(unwrap_unit(unit, &unwrap_options)?);
    }
    for r in &results {
        *times.entry("weld").or_default() += r.seconds_weld;
        *times.entry("charts").or_default() += r.atlas.times.charts;
        *times.entry("pack").or_default() += r.atlas.times.pack;
        *times.entry("check").or_default() += r.atlas.times.check;
    }
    // Write the model.
    let mut written = Vec::new();
    if let (Some(out), Source::File { path, .. }) = (&out, &options.source) {
        progress.stage("writing");
        let t = Instant::now();
        let out_dir = absolute_dir(out)?;
        let model_dir = absolute_dir(path)?;
        let out_file = out_dir.join(out.file_name().ok_or("-o needs a file name")?);
        let all: Vec<NewPrimitive<'_>> = results
            .iter_mut()
            .flat_map(|r| std::mem::take(&mut r.new_primitives))
            .collect();
        let roots = match &options.source {
            Source::File { allowed_roots, .. } => allowed_roots.clone(),
            Source::Mesh(_) => Vec::new(),
        };
        let (bin, copied) = gltf_write::write(
            doc.clone(),
            glb_bin.as_deref(),
            &model_dir,
            &roots,
            &out_file,
            uv_set,
            &all,
        )?;
        written.push(out.display().to_string());
        if bin != out_file {
            written.push(bin.display().to_string());
        }
        if !copied.is_empty() {
            written.push(format!(
                "{} referenced files copied beside it",
                copied.len()
            ));
        }
        times.insert("write", t.elapsed().as_secs_f64());
    }
    // The layout pictures.
    progress.stage("drawing the layout");
    let t = Instant::now();
    let layout_base = options.layout.clone().unwrap_or_else(|| match &out {
        Some(out) => out.with_file_name(format!(
            "{}-uv-layout.png",
            out.file_stem()
                .map_or_else(|| "out".into(), |s| s.to_string_lossy())
        )),
        None => PathBuf::from(format!("{name}-uv-layout.png")),
    });
    let picture_size = options.pack.size.clamp(64, MAX_LAYOUT_PICTURE);
    for (k, r) in results.iter().enumerate() {
        let path = if results.len() == 1 {
            layout_base.clone()
        } else {
            let stem = layout_base
                .file_stem()
                .map_or_else(|| "layout".into(), |s| s.to_string_lossy().into_owned());
            layout_base.with_file_name(format!("{stem}-mesh{}.png", units[k].mesh))
        };
        let (positions, uvs, triangles) = &r.layout;
        let mesh = TriMesh {
            positions: positions.clone(),
            normals: vec![Vec3::Z; positions.len()],
            tangents: vec![Vec4::X; positions.len()],
            uvs: uvs.iter().map(|p| p.as_vec2()).collect(),
            indices: triangles.clone(),
        };
        let picture = draw_uv_layout(&mesh, picture_size, &LayoutOptions::default())?;
        if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
            std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
        }
        write_png(&picture, &path)?;
        written.push(path.display().to_string());
    }
    times.insert("layout", t.elapsed().as_secs_f64());
    // Measure.
    progress.stage("measuring");
    let t = Instant::now();
    let ours: Vec<LayoutStats> = results
        .iter()
        .map(|r| measure(&r.layout.0, &r.layout.1, &r.layout.2))
        .collect();
    let peer = match &options.compare_uvs {
        Some(path) => {
            let (p, uv, tris) = read_peer_uvs(path, results[0].welded.mesh.positions())?;
            Some(measure(&p, &uv, &tris))
        }
        None => None,
    };
    times.insert("measure", t.elapsed().as_secs_f64());
    if let Some(path) = &options.dump_mesh {
        let mesh = &results[0].welded.mesh;
        let positions: Vec<[f64; 3]> = mesh.positions().iter().map(|p| p.to_array()).collect();
        write_json(
            path,
            &json!({"positions": positions, "triangles": mesh.triangles()}),
        )?;
        written.push(path.display().to_string());
    }
    drop(progress);
    let total = started.elapsed().as_secs_f64();
    println!(
        "unwrapped {} mesh(es) of {name} with {:?} into TEXCOORD_{uv_set} ({}×{} texels, padding {}): wrote {}",
        results.len(),
        options.method,
        options.pack.size,
        options.pack.size,
        options.pack.padding,
        written.join(", ")
    );
    let strict_flips: usize = results.iter().map(|r| r.atlas.check.flipped.len()).sum();
    let strict_overlaps: usize = results
        .iter()
        .map(|r| {
            r.atlas.check.overlaps.between_charts.len() + r.atlas.check.overlaps.within_charts.len()
        })
        .sum();
    if options.stats {
        for (k, (r, s)) in results.iter().zip(&ours).enumerate() {
            println!(
                "mesh {} ({} welded vertices, {} triangles): texel density {:.4} texels per unit; \
                 {} charts split because they overlapped themselves",
                units[k].mesh,
                r.welded.mesh.positions().len(),
                r.welded.mesh.triangles().len(),
                r.atlas.pack.texels_per_unit,
                r.atlas.untangled
            );
            for line in s.lines() {
                println!("  {line}");
            }
        }
        println!(
            "exact checks: {strict_flips} triangles not counter-clockwise, {strict_overlaps} \
             overlapping pairs"
        );
        let ms = |s: f64| format!("{:.1} ms", s * 1e3);
        let stages: Vec<String> = times
            .iter()
            .map(|(k, v)| format!("{k} {}", ms(*v)))
            .collect();
        println!("time: {} (total {})", stages.join(", "), ms(total));
        if let Some(p) = &peer {
            println!(
                "compared uvs ({}):",
                options
                    .compare_uvs
                    .as_ref()
                    .map_or(String::new(), |p| p.display().to_string())
            );
            for line in p.lines() {
                println!("  {line}");
            }
        }
    }
    if let Some(path) = &options.stats_json {
        let seconds: serde_json::Map<String, Value> = times
            .iter()
            .map(|(k, v)| ((*k).to_owned(), json!(v)))
            .collect();
        let value = json!({
            "source": name,
            "method": format!("{:?}", options.method),
            "size": options.pack.size,
            "padding": options.pack.padding,
            "meshes": ours.iter().map(LayoutStats::to_json).collect::<Vec<_>>(),
            "seconds": seconds,
            "exact_flips": strict_flips,
            "exact_overlaps": strict_overlaps,
            "compare": peer.as_ref().map(LayoutStats::to_json),
        });
        write_json(path, &value)?;
    }
    if strict_flips > 0 || strict_overlaps > 0 {
        return Err(format!(
            "the exact checks found {strict_flips} flipped triangles and {strict_overlaps} \
             overlapping pairs (files written for inspection; please report)"
        )
        .into());
    }
    Ok(())
}
