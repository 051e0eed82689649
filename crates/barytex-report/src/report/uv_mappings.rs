//! The UV mappings' speed against error: per mapping, the time of `uv` alone, of the analytic
//! Jacobian and of a central finite-difference Jacobian (six more `uv` calls, what a caller
//! without analytic derivatives pays), each Jacobian's error measured against the mapping's own
//! f64 Jacobian (`UvMapping64`).

use barytex_testkit::seeded::XorShift;
use barytex_testkit::uv::{finite_difference_jacobian, surface_points};
use barytex_uv::mappings::{
    BoxMapping, CylinderCaps, Cylindrical, Planar, SphereProjection, Spherical, Torus, UvMapping64,
};
use barytex_uv::{PositionMapping, UvJacobian};
use glam::Vec3;

use super::{ErrorStats, Row, Section, Settings, Table};
use crate::timing::ns_per_call;

/// Finite-difference step, in object units (the objects are of size ~1).
const H: f32 = 1e-3;

trait Mapping: PositionMapping + UvMapping64 {}
impl<T: PositionMapping + UvMapping64> Mapping for T {}

/// Relative Frobenius error of `j` against the f64 Jacobian at `(p, n)`.
fn jacobian_error(m: &dyn Mapping, p: Vec3, n: Vec3, j: UvJacobian) -> Option<f64> {
    let r = m.uv_and_jacobian_f64(p.as_dvec3(), n.as_dvec3())?;
    let err = (j.du.as_dvec3() - r.du).length_squared() + (j.dv.as_dvec3() - r.dv).length_squared();
    let norm = r.du.length_squared() + r.dv.length_squared();
    Some((err / norm).sqrt())
}

fn mappings() -> Vec<(&'static str, Box<dyn Mapping>)> {
    let mut out: Vec<(&'static str, Box<dyn Mapping>)> = Vec::new();
    if let Ok(m) = Planar::xz(2.0) {
        out.push(("Planar::xz", Box::new(m)));
    }
    if let Ok(m) = BoxMapping::new(Vec3::ZERO, 2.0) {
        out.push(("BoxMapping", Box::new(m)));
    }
    if let Ok(m) = Cylindrical::new(1.0, 2.0) {
        out.push((
            "Cylindrical (planar caps)",
            Box::new(m.with_caps(CylinderCaps::Planar)),
        ));
    }
    if let Ok(m) = Spherical::new(1.0, SphereProjection::Equirectangular) {
        out.push(("Spherical, equirectangular", Box::new(m)));
    }
    if let Ok(m) = Spherical::new(1.0, SphereProjection::EqualArea) {
        out.push(("Spherical, equal-area", Box::new(m)));
    }
    if let Ok(m) = Torus::new(2.0, 0.5) {
        out.push(("Torus R = 2, r = ½", Box::new(m)));
    }
    out
}

/// Run the family.
pub(super) fn run(settings: Settings, progress: &mut dyn FnMut(&str)) -> Section {
    let mut tables = Vec::new();
    for (name, m) in mappings() {
        progress(name);
        let pts = surface_points(
            &mut XorShift::new(0x0b5e_2026),
            settings.random,
            name.starts_with("Torus"),
        );
        let m = m.as_ref();
        let analytic: Vec<f64> = pts
            .iter()
            .filter_map(|&(p, n)| jacobian_error(m, p, n, m.uv_and_jacobian(p, n)?))
            .collect();
        let finite_differences: Vec<f64> = pts
            .iter()
            .filter_map(|&(p, n)| jacobian_error(m, p, n, finite_difference_jacobian(m, p, n, H)?))
            .collect();
        let mut table = Table {
            title: format!("{name}: Jacobian"),
            description: format!(
                "{} seeded points (unit sphere between ±75° latitude, or the torus); error: \
                 relative Frobenius norm of the f32 Jacobian against the mapping's f64 one. \
                 `uv` alone: {:.1} ns.",
                pts.len(),
                ns_per_call(&pts, settings.timing, |(p, n)| m.uv(p, n))
            ),
            inputs: pts.len(),
            error_label: "max relative error of the Jacobian".to_owned(),
            ..Table::default()
        };
        table.rows.push(Row {
            method: "uv_and_jacobian (analytic)".to_owned(),
            is_default: true,
            ns: ns_per_call(&pts, settings.timing, |(p, n)| m.uv_and_jacobian(p, n)),
            abs: ErrorStats::of(analytic),
            ..Row::default()
        });
        table.rows.push(Row {
            method: format!("central finite differences of uv (h = {H})"),
            is_default: false,
            ns: ns_per_call(&pts, settings.timing, |(p, n)| {
                finite_difference_jacobian(m, p, n, H)
            }),
            abs: ErrorStats::of(finite_differences),
            ..Row::default()
        });
        table.mark_pareto();
        tables.push(table);
    }
    Section {
        heading: "UV mappings".to_owned(),
        intro: "Each mapping's cost per point and the accuracy of its derivatives: the analytic \
                Jacobian (computed in f64, rounded once) against the finite differences a caller \
                without it would take."
            .to_owned(),
        tables,
        notes: Vec::new(),
    }
}
