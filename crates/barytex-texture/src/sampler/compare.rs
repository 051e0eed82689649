//! Depth comparison for comparison samplers (shadow maps): compare each texel, then filter the
//! 0/1 results (percentage-closer filtering).

use glam::Vec2;

use crate::addressing::{linear_taps, nearest_index, wrap};
use crate::sampler::texel_fetch::Addressing;
use crate::sampler::{CompareFunction, FilterMode};
use crate::{Texel, Texture2d};

/// Whether `reference OP stored` holds.
pub(crate) fn passes(op: CompareFunction, reference: f32, stored: f32) -> bool {
    match op {
        CompareFunction::Never => false,
        CompareFunction::Less => reference < stored,
        CompareFunction::Equal => reference == stored,
        CompareFunction::LessEqual => reference <= stored,
        CompareFunction::Greater => reference > stored,
        CompareFunction::NotEqual => reference != stored,
        CompareFunction::GreaterEqual => reference >= stored,
        CompareFunction::Always => true,
    }
}

/// The filtered comparison result of one level: nearest compares one texel, linear (and cubic,
/// which comparison samplers do not offer) blends the four comparisons bilinearly.
pub(crate) fn filter_level<T: Texel>(
    level: &Texture2d<T>,
    uv: Vec2,
    filter: FilterMode,
    addressing: &Addressing,
    test: impl Fn(f32) -> bool,
) -> f32 {
    let (w, h) = level.size();
    let compared = |x: i64, y: i64| {
        let depth = match (wrap(x, w, addressing.u), wrap(y, h, addressing.v)) {
            (Some(x), Some(y)) => level
                .texel(x, y)
                .map_or(addressing.border.x, |t| t.to_linear().x),
            _ => addressing.border.x,
        };
        if test(depth) { 1.0 } else { 0.0 }
    };
    match filter {
        FilterMode::Nearest => compared(nearest_index(uv.x, w), nearest_index(uv.y, h)),
        FilterMode::Linear | FilterMode::Cubic(_) => {
            let (tx, ty) = (linear_taps(uv.x, w), linear_taps(uv.y, h));
            let (x0, y0) = (tx.i0, ty.i0);
            let (x1, y1) = (x0.saturating_add(1), y0.saturating_add(1));
            let top = compared(x0, y0) + (compared(x1, y0) - compared(x0, y0)) * tx.frac;
            let bottom = compared(x0, y1) + (compared(x1, y1) - compared(x0, y1)) * tx.frac;
            top + (bottom - top) * ty.frac
        }
    }
}
