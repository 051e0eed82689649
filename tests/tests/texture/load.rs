//! Loading through the `image` crate: round trips, formats, and limits enforced before decoding.
#![cfg(feature = "image")]

use barytex_texture::load::{AnyTexture2d, ColorSpace, decoded_size, encode_png, load_from_memory};
use barytex_texture::{Limits, Srgba8, Texture2d, TextureError};

/// A PNG whose header claims `width × height` RGBA8 and whose data is a few bytes.
fn lying_png(width: u32, height: u32) -> Vec<u8> {
    barytex_testkit::png_with_header(
        width,
        height,
        &[0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01],
    )
}

#[test]
fn a_png_claiming_100000_squared_is_refused_before_decoding() {
    let result = load_from_memory(
        &lying_png(100_000, 100_000),
        ColorSpace::Srgb,
        &Limits::default(),
    );
    assert!(
        matches!(
            result,
            Err(TextureError::TooLarge {
                what: "width",
                requested: 100_000,
                ..
            })
        ),
        "{result:?}"
    );
    // Within the side limits but over the byte limit.
    let limits = Limits {
        max_bytes: 1 << 20,
        ..Limits::default()
    };
    let result = load_from_memory(&lying_png(4000, 4000), ColorSpace::Srgb, &limits);
    assert!(
        matches!(result, Err(TextureError::TooLarge { what: "bytes", .. })),
        "{result:?}"
    );
}

#[test]
fn garbage_is_a_decode_error() {
    for bytes in [&b""[..], b"not an image", &lying_png(2, 2)[..20]] {
        let result = load_from_memory(bytes, ColorSpace::Srgb, &Limits::default());
        assert!(matches!(result, Err(TextureError::Decode(_))), "{result:?}");
    }
}

#[test]
fn png_round_trips_in_both_colour_spaces() {
    let texture = Texture2d::from_fn(7, 3, |x, y| Srgba8([x as u8 * 30, y as u8 * 80, 7, 200]))
        .expect("small");
    let png = encode_png(&texture).expect("encode");
    match load_from_memory(&png, ColorSpace::Srgb, &Limits::default()).expect("decode") {
        AnyTexture2d::Srgba8(back) => assert_eq!(back, texture),
        other => panic!("expected Srgba8, got {other:?}"),
    }
    match load_from_memory(&png, ColorSpace::Linear, &Limits::default()).expect("decode") {
        AnyTexture2d::Rgba8(back) => {
            assert_eq!(back.texels()[5].0, texture.texels()[5].0);
        }
        other => panic!("expected Rgba8, got {other:?}"),
    }
}

#[test]
fn sixteen_bit_pngs_load_as_half_floats() {
    let image = image::ImageBuffer::<image::Rgba<u16>, _>::from_fn(4, 2, |x, _| {
        image::Rgba([x as u16 * 20_000, 65_535, 0, 65_535])
    });
    let mut png = Vec::new();
    image
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .expect("encode");
    let loaded = load_from_memory(&png, ColorSpace::Linear, &Limits::default()).expect("decode");
    let AnyTexture2d::Rgba16f(t) = loaded else {
        panic!("expected Rgba16f");
    };
    let linear = t.linear(3, 0).expect("inside");
    assert!((linear.x - 60_000.0 / 65_535.0).abs() < 1e-3, "{linear:?}");
    assert_eq!(linear.y, 1.0);
}

#[test]
fn fixture_textures_load() {
    let Some(fixtures) = barytex_testkit::fixtures_dir() else {
        eprintln!("fixtures absent: skipping");
        return;
    };
    let dir = fixtures.join("gltf/TextureCoordinateTest/glTF");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        eprintln!("{} absent: skipping", dir.display());
        return;
    };
    let mut loaded = 0;
    for entry in entries.flatten() {
        let path = entry.path();
        if path.extension().is_some_and(|e| e == "png" || e == "jpg") {
            let t =
                barytex_texture::load::load_from_path(&path, ColorSpace::Srgb, &Limits::default())
                    .expect("fixture decodes");
            assert!(t.size().0 > 0);
            loaded += 1;
        }
    }
    assert!(loaded > 0, "no image in {}", dir.display());
}

/// The bytes a loaded texture holds: its texel count times its format's texel size.
fn held_bytes(t: &AnyTexture2d) -> u64 {
    let (w, h) = t.size();
    let texel = match t {
        AnyTexture2d::R8(_) => 1,
        AnyTexture2d::Srgba8(_) | AnyTexture2d::Rgba8(_) => 4,
        AnyTexture2d::Rgba16f(_) => 8,
        AnyTexture2d::Rgba32f(_) => 16,
        _ => panic!("unknown format"),
    };
    u64::from(w) * u64::from(h) * texel
}

#[test]
fn decoded_size_predicts_the_loaded_size_from_the_header() {
    fn encode<P: image::PixelWithColorType>(
        image: &image::ImageBuffer<P, Vec<P::Subpixel>>,
    ) -> Vec<u8>
    where
        [P::Subpixel]: image::EncodableLayout,
    {
        let mut png = Vec::new();
        image
            .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .expect("encode");
        png
    }
    let grey = encode(&image::GrayImage::from_pixel(5, 3, image::Luma([7])));
    let rgb = encode(&image::RgbImage::from_pixel(5, 3, image::Rgb([1, 2, 3])));
    let rgba16 = encode(&image::ImageBuffer::<image::Rgba<u16>, _>::from_pixel(
        5,
        3,
        image::Rgba([1, 2, 3, 4]),
    ));
    for (png, srgb, linear) in [(&grey, 60, 15), (&rgb, 60, 60), (&rgba16, 120, 120)] {
        for (space, expected) in [(ColorSpace::Srgb, srgb), (ColorSpace::Linear, linear)] {
            let predicted = decoded_size(png, space).expect("header");
            let loaded = load_from_memory(png, space, &Limits::default()).expect("decode");
            assert_eq!(
                (predicted, held_bytes(&loaded)),
                ((5, 3, expected), expected)
            );
        }
    }
    // From the header alone: a 100 000² claim with no real data is 40 GB, nothing decoded.
    assert_eq!(
        decoded_size(&lying_png(100_000, 100_000), ColorSpace::Srgb).expect("header"),
        (100_000, 100_000, 40_000_000_000)
    );
    assert!(matches!(
        decoded_size(b"not an image", ColorSpace::Srgb),
        Err(TextureError::Decode(_))
    ));
}
