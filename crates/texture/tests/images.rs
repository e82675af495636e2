//! Texture images: PNG loading and its errors, mip chains and texel formats.

use std::path::PathBuf;

use texture::{Error, MipChain, TexelFormat, Texture};

/// A path in the temporary directory unique to this test process and `tag`.
fn temp_path(tag: &str) -> PathBuf {
    std::env::temp_dir().join(format!("edgepaint-texture-{}-{tag}", std::process::id()))
}

/// A texture whose texels are red `reds[j * width + i] / 255` with green and blue 0, alpha 1.
fn reds(width: u32, height: u32, reds: &[u8]) -> Texture {
    let bytes: Vec<u8> = reds.iter().flat_map(|&r| [r, 0, 0, 255]).collect();
    Texture::from_rgba8(width, height, &bytes).unwrap()
}

fn assert_red(t: &Texture, i: u32, j: u32, red: f64) {
    let texel = t.texel(i, j);
    assert!((texel[0] - red / 255.0).abs() < 1e-12, "texel ({i}, {j}) = {texel:?}, want red {red}/255");
}

#[test]
fn png_rows_are_flipped_so_row_0_is_the_bottom() {
    let path = temp_path("flip.png");
    // 2x3, top row first as PNG stores it: row r, column c has red 10 (3 r + c), alpha 100 + r.
    let image =
        ::image::RgbaImage::from_fn(2, 3, |c, r| ::image::Rgba([(10 * (3 * r + c)) as u8, 7, 9, 100 + r as u8]));
    image.save(&path).unwrap();
    let t = Texture::load(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!((t.width(), t.height()), (2, 3));
    assert_eq!(t.name(), path.display().to_string());
    // Texel (i, j) is PNG row 2 - j.
    assert_eq!(t.texel(0, 2), [0.0, 7.0 / 255.0, 9.0 / 255.0, 100.0 / 255.0]);
    assert_eq!(t.texel(1, 2), [10.0 / 255.0, 7.0 / 255.0, 9.0 / 255.0, 100.0 / 255.0]);
    assert_eq!(t.texel(1, 0), [70.0 / 255.0, 7.0 / 255.0, 9.0 / 255.0, 102.0 / 255.0]);
    assert_eq!(t.texels()[0], t.texel(0, 0));
}

#[test]
fn rgb_and_grey_pngs_get_alpha_1() {
    let path = temp_path("rgb.png");
    ::image::RgbImage::from_pixel(2, 2, ::image::Rgb([255, 51, 0])).save(&path).unwrap();
    let rgb = Texture::load(&path).unwrap();
    ::image::GrayImage::from_pixel(1, 1, ::image::Luma([102])).save(&path).unwrap();
    let grey = Texture::load(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert!(rgb.texels().iter().all(|&t| t == [1.0, 0.2, 0.0, 1.0]));
    assert_eq!(grey.texel(0, 0), [0.4, 0.4, 0.4, 1.0]);
}

#[test]
fn a_missing_file_is_named() {
    let path = temp_path("missing.png");
    let err = Texture::load(&path).unwrap_err();
    assert!(matches!(err, Error::Unreadable { .. }), "{err:?}");
    assert!(err.to_string().starts_with(&format!("{}: cannot read", path.display())), "{err}");
}

#[test]
fn a_file_that_is_not_a_png_is_named() {
    let path = temp_path("text.png");
    std::fs::write(&path, "not an image").unwrap();
    let err = Texture::load(&path).unwrap_err();
    std::fs::remove_file(&path).unwrap();
    assert!(matches!(err, Error::Undecodable { .. }), "{err:?}");
    assert!(err.to_string().starts_with(&format!("{}: not a PNG", path.display())), "{err}");
}

#[test]
fn a_3x4_texture_loads_but_does_not_mipmap() {
    let path = temp_path("3x4.png");
    ::image::RgbImage::new(3, 4).save(&path).unwrap();
    let t = Texture::load(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    let err = MipChain::new(t).unwrap_err();
    assert!(matches!(err, Error::NotPowerOfTwo { width: 3, height: 4, .. }), "{err:?}");
    assert_eq!(
        err.to_string(),
        format!(
            "{}: textures are mip-mapped by halving: width and height must be powers of two (got 3x4)",
            path.display()
        )
    );
}

#[test]
fn sizes_are_checked() {
    assert!(matches!(Texture::from_rgba8(0, 4, &[]), Err(Error::ZeroSize { width: 0, height: 4, .. })));
    assert!(matches!(Texture::from_rgba8(4097, 1, &[0; 4 * 4097]), Err(Error::TooLarge { width: 4097, .. })));
    assert!(Texture::from_rgba8(4096, 1, &[0; 4 * 4096]).is_ok());
    let err = Texture::from_rgba8(2, 2, &[0; 15]).unwrap_err();
    assert!(matches!(err, Error::WrongLength { len: 15, .. }), "{err:?}");
    assert!(err.to_string().starts_with("RGBA8 data: "), "{err}");
}

#[test]
fn from_rgba8_takes_rows_from_the_bottom() {
    let t = reds(2, 2, &[1, 2, 3, 4]);
    assert_red(&t, 0, 0, 1.0);
    assert_red(&t, 1, 0, 2.0);
    assert_red(&t, 0, 1, 3.0);
    assert_red(&t, 1, 1, 4.0);
}

#[test]
fn mip_chain_4x4_is_box_filtered_down_to_1x1() {
    // Red of texel (i, j) is 10 (4 j + i): 0..=150.
    let base: Vec<u8> = (0..16).map(|k| 10 * k).collect();
    let chain = MipChain::new(reds(4, 4, &base)).unwrap();
    let levels = chain.levels();
    assert_eq!(levels.len(), 3);
    assert_eq!(chain.base(), &levels[0]);
    assert_eq!((levels[1].width(), levels[1].height()), (2, 2));
    // (0 + 10 + 40 + 50) / 4, (20 + 30 + 60 + 70) / 4, (80 + 90 + 120 + 130) / 4, (100 + 110 + 140 + 150) / 4.
    assert_red(&levels[1], 0, 0, 25.0);
    assert_red(&levels[1], 1, 0, 45.0);
    assert_red(&levels[1], 0, 1, 105.0);
    assert_red(&levels[1], 1, 1, 125.0);
    assert_eq!((levels[2].width(), levels[2].height()), (1, 1));
    assert_red(&levels[2], 0, 0, 75.0);
    assert_eq!(levels[2].texel(0, 0)[3], 1.0);
}

#[test]
fn mip_chain_8x2_keeps_height_1_and_averages_pairs() {
    // Red of texel (i, j) is 10 (8 j + i): row 0 is 0..=70, row 1 is 80..=150.
    let base: Vec<u8> = (0..16).map(|k| 10 * k).collect();
    let chain = MipChain::new(reds(8, 2, &base)).unwrap();
    let sizes: Vec<_> = chain.levels().iter().map(|l| (l.width(), l.height())).collect();
    assert_eq!(sizes, [(8, 2), (4, 1), (2, 1), (1, 1)]);
    // Level 1 texel i: (20 i + 20 i + 10 + 80 + 20 i + 90 + 20 i) / 4 = 20 i + 45.
    for (i, red) in [45.0, 65.0, 85.0, 105.0].into_iter().enumerate() {
        assert_red(&chain.levels()[1], i as u32, 0, red);
    }
    assert_red(&chain.levels()[2], 0, 0, 55.0);
    assert_red(&chain.levels()[2], 1, 0, 95.0);
    assert_red(&chain.levels()[3], 0, 0, 75.0);
}

#[test]
fn non_square_powers_of_two_mipmap() {
    let chain = MipChain::new(Texture::from_rgba8(256, 64, &vec![0; 4 * 256 * 64]).unwrap()).unwrap();
    let sizes: Vec<_> = chain.levels().iter().map(|l| (l.width(), l.height())).collect();
    assert_eq!(sizes, [(256, 64), (128, 32), (64, 16), (32, 8), (16, 4), (8, 2), (4, 1), (2, 1), (1, 1)]);
    let one = MipChain::new(reds(1, 1, &[9])).unwrap();
    assert_eq!(one.levels().len(), 1);
}

#[test]
fn every_code_of_every_channel_round_trips() {
    for format in TexelFormat::ALL {
        let bits = format.bits();
        let mut shift = 0;
        for k in (0..4).rev().filter(|&k| bits[k] > 0) {
            let max = (1u32 << bits[k]) - 1;
            for v in 0..=max {
                let word = v << shift;
                let rgba = format.decode(word);
                assert_eq!(rgba[k], f64::from(v) / f64::from(max), "{format:?} channel {k} code {v}");
                assert_eq!(format.encode(rgba), word, "{format:?} channel {k} code {v}");
            }
            shift += bits[k];
        }
    }
}

#[test]
fn formats_pack_red_high_and_alpha_low() {
    assert_eq!(TexelFormat::Rgb565.encode([1.0; 4]), 0xFFFF);
    assert_eq!(TexelFormat::Rgb565.encode([1.0, 0.0, 0.0, 0.0]), 0xF800);
    assert_eq!(TexelFormat::Rgb565.decode(0x07E0), [0.0, 1.0, 0.0, 1.0]);
    assert_eq!(TexelFormat::Rgb888.encode([1.0, 0.5, 0.0, 0.0]), 0xFF8000);
    // 0.5 * 255 = 127.5 rounds to 128 = 0x80.
    assert_eq!(TexelFormat::Rgba8888.encode([1.0, 0.0, 0.5, 1.0]), 0xFF00_80FF);
    assert_eq!(TexelFormat::Rgba4444.encode([0.0, 0.0, 0.0, 1.0]), 0x000F);
    // Out of range and NaN clamp.
    assert_eq!(TexelFormat::Rgba4444.encode([2.0, -1.0, f64::NAN, 1.0]), 0xF00F);
    let sizes: Vec<_> = TexelFormat::ALL.iter().map(|f| f.bytes_per_texel()).collect();
    assert_eq!(sizes, [2, 2, 2, 3, 4]);
    assert_eq!(TexelFormat::default(), TexelFormat::Rgba8888);
}

#[test]
fn rgba5551_alpha_is_one_bit() {
    let f = TexelFormat::Rgba5551;
    assert_eq!(f.encode([0.0, 0.0, 0.0, 0.49]), 0);
    assert_eq!(f.encode([0.0, 0.0, 0.0, 0.5]), 1);
    assert_eq!(f.encode([1.0, 1.0, 1.0, 0.0]), 0xFFFE);
    assert_eq!(f.decode(1), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(f.decode(0xFFFE), [1.0, 1.0, 1.0, 0.0]);
    assert_eq!(f.quantize([0.2, 0.2, 0.2, 0.7])[3], 1.0);
}

#[test]
fn quantizing_a_texture_rounds_each_texel() {
    // 100 / 255 * 15 = 5.88 rounds to 6, which decodes as 6 / 15 = 0.4.
    let t = reds(1, 1, &[100]).quantized(TexelFormat::Rgba4444);
    assert_eq!(t.texel(0, 0), [0.4, 0.0, 0.0, 1.0]);
    let chain = MipChain::new(reds(2, 1, &[100, 100])).unwrap().quantized(TexelFormat::Rgba4444);
    assert_eq!(chain.levels()[1].texel(0, 0), [0.4, 0.0, 0.0, 1.0]);
}

#[test]
fn levels_given_one_by_one_make_a_chain_when_their_sizes_halve() {
    let level = |w: u32, h: u32, red: u8| reds(w, h, &vec![red; (w * h) as usize]);
    let chain = MipChain::from_levels(vec![level(4, 2, 10), level(2, 1, 20), level(1, 1, 30)]).unwrap();
    assert_eq!(chain.levels().len(), 3);
    assert_red(&chain.levels()[1], 1, 0, 20.0);
    let e = MipChain::from_levels(vec![level(4, 2, 10), level(2, 2, 20), level(1, 1, 30)]).unwrap_err().to_string();
    assert!(e.contains("mip level 1 is 2x2; level 1 of a 4x2 texture is 2x1"), "{e}");
    let e = MipChain::from_levels(vec![level(4, 2, 10), level(2, 1, 20)]).unwrap_err().to_string();
    assert!(e.contains("2 mip levels given; a 4x2 texture has 3"), "{e}");
    let e = MipChain::from_levels(vec![level(3, 1, 10)]).unwrap_err().to_string();
    assert!(e.contains("powers of two"), "{e}");
    assert!(MipChain::from_levels(Vec::new()).is_err());
}
