//! The texture environment and framebuffer blending, one hand-computed example a mode.

use texture::{blend, environment, BlendFactor, BlendMode, EnvMode, Rgba};

fn assert_close(got: Rgba, want: Rgba, what: &str) {
    assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-12), "{what}: {got:?}, want {want:?}");
}

#[test]
fn every_texture_function() {
    let cf = [0.5, 0.2, 0.8, 0.6];
    let cs = [0.4, 1.0, 0.5, 0.25];
    let cc = [1.0, 0.0, 0.5, 0.3];
    let table = [
        (EnvMode::Replace, [0.4, 1.0, 0.5, 0.25]),
        (EnvMode::Modulate, [0.2, 0.2, 0.4, 0.15]),
        // Cf 0.75 + Cs 0.25; A = Af.
        (EnvMode::Decal, [0.475, 0.4, 0.725, 0.6]),
        // Cf (1 - Cs) + Cc Cs: 0.5 * 0.6 + 0.4, 0.2 * 0 + 0, 0.8 * 0.5 + 0.25.
        (EnvMode::Blend, [0.7, 0.0, 0.65, 0.15]),
        // 0.7, 1.2 and 1.3 clamp to 1.
        (EnvMode::Add, [0.9, 1.0, 1.0, 0.15]),
    ];
    for (mode, want) in table {
        assert_close(environment(mode, cf, cs, cc), want, &format!("{mode:?}"));
    }
    assert_eq!(EnvMode::default(), EnvMode::Modulate);
}

#[test]
fn every_blend_mode() {
    let src = [0.8, 0.4, 0.2, 0.5];
    let dst = [0.1, 0.6, 1.0, 0.4];
    let table = [
        (BlendMode::Opaque, [0.8, 0.4, 0.2, 0.5]),
        (BlendMode::Alpha, [0.45, 0.5, 0.6, 0.45]),
        // 0.9, 1.0, 1.2 clamped, 0.9.
        (BlendMode::Additive, [0.9, 1.0, 1.0, 0.9]),
        (BlendMode::Multiply, [0.08, 0.24, 0.2, 0.2]),
        (BlendMode::PremultipliedAlpha, [0.85, 0.7, 0.7, 0.7]),
        // 0.4 + 0.1, 0.2 + 0.6, 0.1 + 1.0 clamped, 0.25 + 0.4.
        (BlendMode::AlphaAdditive, [0.5, 0.8, 1.0, 0.65]),
    ];
    for (mode, want) in table {
        assert_close(blend(mode, src, dst), want, &format!("{mode:?}"));
    }
    assert_eq!(BlendMode::default(), BlendMode::Opaque);
    assert_eq!(BlendMode::Alpha.factors(), (BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha));
}

#[test]
fn modes_read_snake_case_json() {
    let modes: Vec<BlendMode> =
        serde_json::from_str(r#"["premultiplied_alpha", "alpha_additive", "multiply"]"#).unwrap();
    assert_eq!(modes, [BlendMode::PremultipliedAlpha, BlendMode::AlphaAdditive, BlendMode::Multiply]);
    assert_eq!(serde_json::from_str::<EnvMode>(r#""modulate""#).unwrap(), EnvMode::Modulate);
    assert_eq!(serde_json::to_string(&texture::TexelFormat::Rgba5551).unwrap(), r#""rgba5551""#);
}
