//! The anisotropic footprint of a pixel: its major and minor axes, and the two ways of
//! integrating it — GPU-style probes along the major axis (Vulkan/D3D) and the ellipse that EWA
//! weights (Heckbert; pbrt-v4).

use glam::Vec2;

use crate::sampler::ewa::Ellipse;

/// A pixel footprint in texture space: the derivative vectors sorted by length in texels.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Footprint {
    /// The longer derivative, in uv units.
    major: Vec2,
    /// The shorter derivative, in uv units.
    minor: Vec2,
    /// Lengths in texels of the base level.
    major_texels: f32,
    minor_texels: f32,
    size: Vec2,
}

/// GPU-style anisotropic filtering: `count` trilinear probes spaced evenly along the major axis,
/// each at level `lod` (chosen so one probe covers `major / count` texels).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ProbePlan {
    pub(crate) count: usize,
    pub(crate) lod: f32,
    major: Vec2,
    /// Whether the footprint's major axis spans more than one texel of the base level: only
    /// then are the probes spread along it. A probe level at or below 0 does not mean the pixel
    /// is magnified — `count` probes one texel apart each sit at level 0 — so the single-probe
    /// shortcut is decided on the major axis itself.
    pub(crate) spread: bool,
}

impl ProbePlan {
    /// The offset of probe `i` from the footprint's centre: `major·((i + ½)/count − ½)`.
    #[inline]
    pub(crate) fn offset(&self, i: usize) -> Vec2 {
        self.major * ((i as f32 + 0.5) / self.count as f32 - 0.5)
    }
}

impl Footprint {
    /// `None` when a derivative is not finite or both are zero (the isotropic path then applies:
    /// magnification, or the most blurred level).
    pub(crate) fn new(ddx: Vec2, ddy: Vec2, size: (u32, u32)) -> Option<Self> {
        if !ddx.is_finite() || !ddy.is_finite() {
            return None;
        }
        let size = Vec2::new(size.0 as f32, size.1 as f32);
        let (lx, ly) = ((ddx * size).length(), (ddy * size).length());
        if !(lx.is_finite() && ly.is_finite()) || (lx == 0.0 && ly == 0.0) {
            return None;
        }
        let (major, minor, major_texels, minor_texels) = if lx >= ly {
            (ddx, ddy, lx, ly)
        } else {
            (ddy, ddx, ly, lx)
        };
        Some(Self {
            major,
            minor,
            major_texels,
            minor_texels,
            size,
        })
    }

    /// Vulkan/D3D: `N = min(⌈major/minor⌉, max_anisotropy)` probes, at
    /// `λ = log₂ max(major/N, minor)`.
    ///
    /// The specifications' `λ = log₂(major/N)` (EXT_texture_filter_anisotropic) reads a level
    /// finer than the minor axis whenever `major/minor` is not an integer (`N` rounds up): at
    /// a ratio of 1.06 two probes sample a level one texel per probe where the footprint is 1.9
    /// texels across, and the minor axis aliases — on rows alternating 0 and 1 the result was
    /// 0.86 where the footprint averages 0.53 and one probe gave 0.50 (found by the property
    /// test `more_probes_are_not_worse`). No probe's level is finer than the minor axis now;
    /// where `N` is the ratio itself, or the clamp, the two formulas agree.
    pub(crate) fn probes(&self, max_anisotropy: f32) -> ProbePlan {
        let ratio = if self.minor_texels > 0.0 {
            (self.major_texels / self.minor_texels).ceil()
        } else {
            max_anisotropy
        };
        let count = ratio.clamp(1.0, max_anisotropy);
        ProbePlan {
            // count ∈ [1, 16].
            count: count as usize,
            lod: (self.major_texels / count).max(self.minor_texels).log2(),
            major: self.major,
            spread: self.major_texels > 1.0,
        }
    }

    /// pbrt-v4's EWA footprint: the minor axis lengthened so the eccentricity is at most
    /// `max_anisotropy` (bounding the texels visited), the level chosen from the minor axis.
    pub(crate) fn ewa_ellipse(&self, max_anisotropy: f32) -> Ellipse {
        let mut minor = self.minor;
        let mut minor_texels = self.minor_texels;
        let wanted = self.major_texels / max_anisotropy;
        if minor_texels < wanted {
            if minor_texels > 0.0 {
                minor *= wanted / minor_texels;
            } else {
                // A degenerate (line) footprint: widen it perpendicular to the major axis, in
                // texel space so the widening is isotropic in texels.
                let major_t = self.major * self.size;
                let perp_t = Vec2::new(-major_t.y, major_t.x) / self.major_texels * wanted;
                minor = perp_t / self.size;
            }
            minor_texels = wanted;
        }
        Ellipse {
            axis0: self.major,
            axis1: minor,
            lod: minor_texels.log2(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn probe_count_follows_the_axis_ratio_and_the_clamp() {
        let f = Footprint::new(
            Vec2::new(8.0 / 64.0, 0.0),
            Vec2::new(0.0, 2.0 / 64.0),
            (64, 64),
        )
        .expect("finite");
        let plan = f.probes(16.0);
        assert_eq!(plan.count, 4);
        assert_eq!(plan.lod, 1.0);
        assert_eq!(plan.offset(0), Vec2::new(-3.0 / 64.0, 0.0));
        let clamped = f.probes(2.0);
        assert_eq!(clamped.count, 2);
        assert_eq!(clamped.lod, 2.0);
        assert!(Footprint::new(Vec2::ZERO, Vec2::ZERO, (4, 4)).is_none());
        assert!(Footprint::new(Vec2::NAN, Vec2::X, (4, 4)).is_none());
    }

    #[test]
    fn ewa_minor_axis_is_widened_to_the_clamp() {
        let f = Footprint::new(Vec2::new(16.0 / 64.0, 0.0), Vec2::ZERO, (64, 64)).expect("finite");
        let e = f.ewa_ellipse(8.0);
        assert_eq!(e.lod, 1.0);
        // The 16-texel major axis stays; the zero minor axis becomes 16 / 8 = 2 texels.
        assert!(((e.axis0 * 64.0).length() - 16.0).abs() < 1e-5, "{e:?}");
        assert!(((e.axis1 * 64.0).length() - 2.0).abs() < 1e-6, "{e:?}");
        assert!((e.axis0.dot(e.axis1)).abs() < 1e-9);
    }
}
