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

/// CRC-32 (ISO 3309, as PNG chunks use), bit by bit.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0_u32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

/// Pixel data corrupted where the checks before decoding cannot see it (bytes of the IDAT
/// chunk changed, its CRC recomputed): the row-by-row path and the `image` crate agree on every
/// file — the same texels, or both refuse it (with the same message, since a failing row hands
/// the file to the `image` crate).
#[test]
fn corrupted_pixel_data_loads_or_fails_as_in_the_image_crate() {
    let clean = rgb_png(23, 17, None);
    // The IDAT chunk: its length, then "IDAT", its data and the CRC.
    let at = clean
        .windows(4)
        .position(|w| w == b"IDAT")
        .expect("an IDAT chunk")
        - 4;
    let length = u32::from_be_bytes(clean[at..at + 4].try_into().expect("4 bytes")) as usize;
    let data = at + 8..at + 8 + length;
    let mut state = 0x2545_f491_u32;
    let mut outcomes = [0_usize; 2];
    for _ in 0..400 {
        let mut bytes = clean.clone();
        for _ in 0..1 + state % 3 {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            let i = data.start + state as usize % length;
            bytes[i] ^= (state >> 24) as u8 | 1;
        }
        let crc = crc32(&bytes[at + 4..data.end]).to_be_bytes();
        bytes[data.end..data.end + 4].copy_from_slice(&crc);
        let expected = image::load_from_memory(&bytes).map(|i| i.into_rgba8().into_raw());
        let got = load_from_memory(&bytes, ColorSpace::Srgb, &Limits::default());
        match (got, expected) {
            (Ok(texture), Ok(texels)) => {
                outcomes[0] += 1;
                assert_eq!(rgba_bytes(&texture), texels);
            }
            (Err(barytex_texture::TextureError::Decode(m)), Err(e)) => {
                outcomes[1] += 1;
                assert_eq!(m, e.to_string());
            }
            (got, expected) => panic!("barytex {got:?}, image {:?}", expected.map(|_| ())),
        }
    }
    // Both outcomes occur: the comparison covers decodable and undecodable corruptions.
    assert!(outcomes[0] > 0 && outcomes[1] > 0, "{outcomes:?}");
}
