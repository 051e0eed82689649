//! Every 8-bit PNG layout loads into the texels the `image` crate's own RGBA conversion gives
//! (grey expanded, alpha 255 where the file has none), in both colour spaces — the 8-bit RGB and
//! RGBA PNGs decoded row by row straight into texels among them — and the files that path
//! leaves to the `image` crate (a `tRNS` colour key, a broken file) load or fail as there.
#![cfg(feature = "image")]

use barytex_texture::Limits;
use barytex_texture::load::{AnyTexture2d, ColorSpace, load_from_memory};
use image::{DynamicImage, ImageFormat};

/// Pseudo-random bytes (xorshift).
fn noise(n: usize, seed: u32) -> Vec<u8> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 17;
            s ^= s << 5;
            (s >> 24) as u8
        })
        .collect()
}

fn png(image: &DynamicImage) -> Vec<u8> {
    let mut bytes = std::io::Cursor::new(Vec::new());
    image
        .write_to(&mut bytes, ImageFormat::Png)
        .expect("encodes");
    bytes.into_inner()
}

/// The texels of an 8-bit texture as RGBA bytes.
fn rgba_bytes(texture: &AnyTexture2d) -> Vec<u8> {
    match texture {
        AnyTexture2d::Srgba8(t) => t.texels().iter().flat_map(|t| t.0).collect(),
        AnyTexture2d::Rgba8(t) => t.texels().iter().flat_map(|t| t.0).collect(),
        _ => panic!("an 8-bit colour PNG loads as Srgba8 or Rgba8"),
    }
}

#[test]
fn every_8_bit_layout_loads_as_the_image_crates_rgba() {
    let (w, h) = (37, 23);
    let n = (w * h) as usize;
    let layouts = [
        DynamicImage::ImageRgb8(image::RgbImage::from_raw(w, h, noise(3 * n, 1)).expect("size")),
        DynamicImage::ImageRgba8(image::RgbaImage::from_raw(w, h, noise(4 * n, 2)).expect("size")),
        DynamicImage::ImageLumaA8(
            image::GrayAlphaImage::from_raw(w, h, noise(2 * n, 3)).expect("size"),
        ),
        DynamicImage::ImageLuma8(image::GrayImage::from_raw(w, h, noise(n, 4)).expect("size")),
    ];
    for layout in &layouts {
        let bytes = png(layout);
        let expected = image::load_from_memory(&bytes)
            .expect("decodes")
            .into_rgba8()
            .into_raw();
        for space in [ColorSpace::Srgb, ColorSpace::Linear] {
            let texture = load_from_memory(&bytes, space, &Limits::default()).expect("loads");
            assert_eq!(texture.size(), (w, h));
            if let (DynamicImage::ImageLuma8(grey), ColorSpace::Linear) = (layout, space) {
                // Grey linear data stays one channel.
                let AnyTexture2d::R8(t) = &texture else {
                    panic!("8-bit grey as linear data loads as R8");
                };
                let got: Vec<u8> = t.texels().iter().map(|t| t.0).collect();
                assert_eq!(&got, grey.as_raw());
                continue;
            }
            match (&texture, space) {
                (AnyTexture2d::Srgba8(_), ColorSpace::Srgb)
                | (AnyTexture2d::Rgba8(_), ColorSpace::Linear) => {}
                _ => panic!("{:?} loads in the colour space asked for", layout.color()),
            }
            assert_eq!(
                rgba_bytes(&texture),
                expected,
                "{:?} {space:?}",
                layout.color()
            );
        }
    }
}

/// An 8-bit RGB PNG of `w × h` noise texels, with a `tRNS` colour key when `key` is given.
fn rgb_png(w: u32, h: u32, key: Option<[u8; 3]>) -> Vec<u8> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, w, h);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    if let Some([r, g, b]) = key {
        // 16-bit samples in the chunk, as PNG §11.3.2.1 stores them.
        encoder.set_trns(vec![0, r, 0, g, 0, b]);
    }
    let mut writer = encoder.write_header().expect("header");
    let mut data = noise((3 * w * h) as usize, 7);
    if let Some(key) = key {
        // A few texels take the key's colour.
        for k in (0..data.len() / 3).step_by(5) {
            data[3 * k..3 * k + 3].copy_from_slice(&key);
        }
    }
    writer.write_image_data(&data).expect("data");
    writer.finish().expect("finishes");
    bytes
}

#[test]
fn an_rgb_colour_key_becomes_alpha_as_in_the_image_crate() {
    let bytes = rgb_png(19, 11, Some([10, 20, 30]));
    let expected = image::load_from_memory(&bytes)
        .expect("decodes")
        .into_rgba8()
        .into_raw();
    assert!(
        expected.chunks_exact(4).any(|t| t[3] == 0),
        "the key made some texels transparent"
    );
    let texture = load_from_memory(&bytes, ColorSpace::Srgb, &Limits::default()).expect("loads");
    assert_eq!(rgba_bytes(&texture), expected);
}

#[test]
fn a_broken_rgb_png_fails_with_the_image_crates_message() {
    let bytes = rgb_png(64, 64, None);
    // Cut inside the pixel data: the header is whole, the rows are not.
    let cut = &bytes[..bytes.len() / 2];
    let expected = image::load_from_memory(cut)
        .expect_err("truncated")
        .to_string();
    match load_from_memory(cut, ColorSpace::Srgb, &Limits::default()) {
        Err(barytex_texture::TextureError::Decode(message)) => assert_eq!(message, expected),
        other => panic!("expected a decoding error, got {other:?}"),
    }
}
