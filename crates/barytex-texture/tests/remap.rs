//! The bilinear remap against an exact f64 bilinear reference.

use barytex_texture::remap::remap_bilinear_rgba8;
use barytex_texture::{Rgba8, Texture2d, TextureError};
use glam::Vec2;
use proptest::prelude::*;

fn exact_bilinear(src: &Texture2d<Rgba8>, uv: Vec2) -> [f64; 4] {
    let (w, h) = src.size();
    let x = f64::from(uv.x) * f64::from(w) - 0.5;
    let y = f64::from(uv.y) * f64::from(h) - 0.5;
    let (fx, fy) = (x - x.floor(), y - y.floor());
    let (x0, y0) = (x.floor() as i64, y.floor() as i64);
    let at = |i: i64, j: i64| {
        let i = i.clamp(0, i64::from(w) - 1) as u32;
        let j = j.clamp(0, i64::from(h) - 1) as u32;
        src.texel(i, j).expect("clamped").0.map(f64::from)
    };
    let (c00, c10, c01, c11) = (
        at(x0, y0),
        at(x0 + 1, y0),
        at(x0, y0 + 1),
        at(x0 + 1, y0 + 1),
    );
    core::array::from_fn(|c| {
        let top = c00[c] * (1.0 - fx) + c10[c] * fx;
        let bottom = c01[c] * (1.0 - fx) + c11[c] * fx;
        top * (1.0 - fy) + bottom * fy
    })
}

proptest! {
    /// Every channel within half a step (plus the blend's f32 rounding) of the exact value.
    #[test]
    fn remap_matches_exact_bilinear(
        w in 1_u32..40, h in 1_u32..40, seed in any::<u64>(),
        coords in prop::collection::vec((-0.2_f32..1.2, -0.2_f32..1.2), 1..64),
    ) {
        let mut state = seed | 1;
        let src = Texture2d::from_fn(w, h, |_, _| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let b = state.to_le_bytes();
            Rgba8([b[0], b[1], b[2], b[3]])
        }).expect("small");
        let coords: Vec<Vec2> = coords.into_iter().map(|(u, v)| Vec2::new(u, v)).collect();
        let mut out = vec![Rgba8::default(); coords.len()];
        remap_bilinear_rgba8(&src, &coords, &mut out).expect("same length");
        for (uv, o) in coords.iter().zip(&out) {
            let want = exact_bilinear(&src, *uv);
            for (c, want_c) in want.iter().enumerate() {
                let err = (f64::from(o.0[c]) - want_c).abs();
                prop_assert!(err <= 0.5 + 1.0 / 16384.0, "{uv:?} channel {c}: {} vs {}", o.0[c], want_c);
            }
        }
    }
}

#[test]
fn lengths_must_match_and_bad_coordinates_are_black() {
    let src = Texture2d::new(4, 4, Rgba8([9; 4])).expect("4²");
    let mut out = vec![Rgba8::default(); 2];
    assert!(matches!(
        remap_bilinear_rgba8(&src, &[Vec2::ZERO], &mut out),
        Err(TextureError::DataLength { .. })
    ));
    remap_bilinear_rgba8(&src, &[Vec2::NAN, Vec2::splat(1e30)], &mut out).expect("same length");
    assert_eq!(out, [Rgba8([0; 4]), Rgba8([9; 4])]);
}
