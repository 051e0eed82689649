//! The whole pipeline: charts (parameterization), packing, and the exact checks.
//!
//! [`unwrap`] builds charts with the chosen [`Method`], packs them into the unit square
//! ([`pack`](crate::pack::pack)), rounds every uv to f32 (what a glTF file stores, so what is
//! checked is what is written), and checks the result exactly ([`check_atlas`]).

mod check;
mod flatten;

use std::time::Instant;

use glam::DVec2;

pub use check::{AtlasCheck, check_atlas};
pub use flatten::MIN_ASPECT;

use crate::pack::{PackOptions, PackStats, pack};
use crate::{Chart, UnwrapError, UnwrapMesh};

/// How charts are made.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum Method {
    /// One chart per triangle, laid flat without distortion (a lightmapper's layout: no
    /// distortion, a seam on every edge, three vertices per triangle).
    PerTriangle,
    /// Two triangles sharing an edge per chart, unfolded flat about it without distortion (a
    /// triangulated quad becomes one chart), and single triangles where no neighbour is left.
    /// Half the charts and seams of [`Method::PerTriangle`], and charts that fill their boxes.
    #[default]
    TrianglePairs,
}

/// How to unwrap.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UnwrapOptions {
    /// How charts are made.
    pub method: Method,
    /// How they are packed.
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
    /// Packing's scale and efficiency.
    pub pack: PackStats,
    /// The exact checks of the packed, rounded charts.
    pub check: AtlasCheck,
    /// Seconds per stage.
    pub times: StageTimes,
}

/// Unwraps a mesh: charts by `options.method`, packed by `options.pack`, rounded to f32,
/// checked exactly. The checks' findings are in [`Atlas::check`] (an atlas with a flip or an
/// overlap is returned, not hidden; [`AtlasCheck::is_valid`] says whether there is any).
///
/// # Errors
/// [`UnwrapError::Pack`] when the options are out of range or the charts do not fit.
///
/// ```
/// use barytex_unwrap::{UnwrapMesh, UnwrapOptions, unwrap};
/// use glam::DVec3;
///
/// // A unit cube's six faces, two triangles each.
/// let p: Vec<DVec3> = (0..8).map(|i| DVec3::new((i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64)).collect();
/// let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
/// let tris: Vec<[u32; 3]> = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
/// let atlas = unwrap(&UnwrapMesh::new(p, tris)?, &UnwrapOptions::default())?;
/// assert_eq!(atlas.charts.len(), 6); // one square chart per face
/// assert!(atlas.check.is_valid());
/// assert!(atlas.pack.efficiency > 0.5);
/// # Ok::<(), barytex_unwrap::UnwrapError>(())
/// ```
pub fn unwrap(mesh: &UnwrapMesh, options: &UnwrapOptions) -> Result<Atlas, UnwrapError> {
    options.pack.validate().map_err(UnwrapError::Pack)?;
    let started = Instant::now();
    let mut charts = match options.method {
        Method::PerTriangle => flatten::per_triangle(mesh),
        Method::TrianglePairs => flatten::triangle_pairs(mesh),
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
        pack: pack_stats,
        check,
        times: StageTimes {
            charts: (charts_done - started).as_secs_f64(),
            pack: (packed - charts_done).as_secs_f64(),
            check: (checked - packed).as_secs_f64(),
        },
    })
}
