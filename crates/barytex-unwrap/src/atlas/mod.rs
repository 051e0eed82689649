//! The whole pipeline: charts (parameterization), packing, and the exact checks.
//!
//! [`unwrap`] builds charts with the chosen [`ChartMethod`] (splitting any parameterized chart
//! that overlaps itself until none does), packs them into the unit square
//! ([`pack`](crate::pack::pack)), rounds every uv to f32 (what a glTF file stores, so what is
//! checked is what is written), and checks the result exactly ([`check_atlas`]).

mod check;
mod flatten;
mod untangle;

use std::time::Instant;

use glam::DVec2;

pub use check::{AtlasCheck, check_atlas};
pub use flatten::MIN_ASPECT;

use crate::pack::{PackOptions, PackStats, pack};
use crate::{Chart, ParamOptions, UnwrapError, UnwrapMesh, parameterize};

/// How [`unwrap`] makes charts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum ChartMethod {
    /// Segmentation into disk charts and one parameterization per chart: [`parameterize`] with
    /// [`UnwrapOptions::param`] (LSCM with ARAP refinement by default).
    #[default]
    Parameterize,
    /// One chart per triangle, laid flat without distortion (a lightmapper's layout: no
    /// distortion, a seam on every edge, three vertices per triangle).
    PerTriangle,
    /// Two triangles sharing an edge per chart, unfolded flat about it without distortion (a
    /// triangulated quad becomes one chart), and single triangles where no neighbour is left.
    /// Half the charts and seams of [`ChartMethod::PerTriangle`], and charts that fill their
    /// boxes.
    TrianglePairs,
}

/// How to unwrap.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct UnwrapOptions {
    /// How charts are made.
    pub charts: ChartMethod,
    /// The parameterization's options, for [`ChartMethod::Parameterize`].
    pub param: ParamOptions,
    /// How charts are packed.
    pub pack: PackOptions,
}

/// Seconds spent in each stage of [`unwrap`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StageTimes {
    /// Making the charts.
    pub charts: f64,
    /// Packing them.
    pub pack: f64,
    /// The exact checks.
    pub check: f64,
}

/// An unwrapped mesh: its charts with uvs in the unit square (each uv a value an f32 holds
/// exactly), what packing did, what the exact checks found, and the time of each stage.
#[derive(Clone, Debug, PartialEq)]
pub struct Atlas {
    /// The charts, uvs packed in `[0, 1]²`.
    pub charts: Vec<Chart>,
    /// Charts of [`parameterize`] that overlapped themselves (exactly) and were split in two and
    /// parameterized again, recursively, until none did.
    pub untangled: usize,
    /// Packing's scale and efficiency.
    pub pack: PackStats,
    /// The exact checks of the packed, rounded charts.
    pub check: AtlasCheck,
    /// Seconds per stage.
    pub times: StageTimes,
}

/// Unwraps a mesh: charts by `options.charts`, packed by `options.pack`, rounded to f32,
/// checked exactly. The checks' findings are in [`Atlas::check`] (an atlas with a flip or an
/// overlap is returned, not hidden; [`AtlasCheck::is_valid`] says whether there is any).
///
/// # Errors
/// [`UnwrapError::Pack`] when the pack options are out of range or the charts do not fit; the
/// errors of [`parameterize`] for [`ChartMethod::Parameterize`].
///
/// ```
/// use barytex_unwrap::{ChartMethod, UnwrapMesh, UnwrapOptions, unwrap};
/// use glam::DVec3;
///
/// // A unit cube's six faces, two triangles each.
/// let p: Vec<DVec3> = (0..8).map(|i| DVec3::new((i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64)).collect();
/// let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
/// let tris: Vec<[u32; 3]> = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
/// let mesh = UnwrapMesh::new(p, tris)?;
/// let atlas = unwrap(&mesh, &UnwrapOptions::default())?;
/// assert!(atlas.check.is_valid());
/// // Unfolded pairs: one square chart per face, no distortion.
/// let pairs = UnwrapOptions { charts: ChartMethod::TrianglePairs, ..UnwrapOptions::default() };
/// let atlas = unwrap(&mesh, &pairs)?;
/// assert_eq!(atlas.charts.len(), 6);
/// assert!(atlas.check.is_valid());
/// assert!(atlas.pack.efficiency > 0.5);
/// # Ok::<(), barytex_unwrap::UnwrapError>(())
/// ```
pub fn unwrap(mesh: &UnwrapMesh, options: &UnwrapOptions) -> Result<Atlas, UnwrapError> {
    options.pack.validate().map_err(UnwrapError::Pack)?;
    let started = Instant::now();
    let mut untangled = 0;
    let mut charts = match options.charts {
        ChartMethod::Parameterize => {
            let charts = parameterize(mesh, &options.param)?;
            let (charts, splits) = untangle::untangle(mesh, charts, &options.param)?;
            untangled = splits;
            charts
        }
        ChartMethod::PerTriangle => flatten::per_triangle(mesh),
        ChartMethod::TrianglePairs => flatten::triangle_pairs(mesh),
    };
    let charts_done = Instant::now();
    let pack_stats = pack(&mut charts, &options.pack).map_err(UnwrapError::Pack)?;
    for uv in charts.iter_mut().flat_map(|c| c.uvs.iter_mut()) {
        *uv = DVec2::new(f64::from(uv.x as f32), f64::from(uv.y as f32));
    }
    let packed = Instant::now();
    let check = check_atlas(&charts);
    let checked = Instant::now();
    Ok(Atlas {
        charts,
        untangled,
        pack: pack_stats,
        check,
        times: StageTimes {
            charts: (charts_done - started).as_secs_f64(),
            pack: (packed - charts_done).as_secs_f64(),
            check: (checked - packed).as_secs_f64(),
        },
    })
}
