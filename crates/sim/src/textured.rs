//! Whole frames through the textured `raster_top` (`rtl::raster_top_textured`, `TEXTURE =
//! 1`): the triangles with their texture words in (`model::texture_path::sent`), the depth
//! and colour buffers in Rust ([`Memory`], which returns colour for blending) and the
//! texture memory behind `texture_path`'s read port (`model::texture_memory::ReadPort`). The frame simulation
//! of `edgepaint render --engine rtl` on textured and blended scenes and of the textured
//! `raster_top`'s tests.
//!
//! Cycle 0 is the first cycle the first triangle is offered; a triangle is offered as soon
//! as the one before it is taken; [`TexturedOut::cycles`] is the cycle `done` is first high.

use crate::memory::{Memory, ReadDuringWrite, Request, REQUEST};
use crate::streams::raw;
use crate::{Outputs, Sim, Value, VlSim};
use fx::Build;
use model::blend::MODES;
use model::texture_cache::MemAsk;
use model::texture_memory::ReadPort;
use model::texture_path::Sent;
use model::texture_unit::TexState;
use texture::{EnvMode, Filter, MipMode, TexelFormat, Weights, Wrap};

/// `texture_unit`'s codes of the wrap modes, the mip modes and the environments.
pub const WRAPS: [Wrap; 3] = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge];
pub const MIPS: [MipMode; 3] = [MipMode::None, MipMode::Nearest, MipMode::Linear];
pub const ENVS: [EnvMode; 5] = [EnvMode::Replace, EnvMode::Modulate, EnvMode::Decal, EnvMode::Blend, EnvMode::Add];

/// The build the textured `raster_top` is made at: size class 10, its default formats.
pub const BUILD: Build = Build { class: 10, formats: rtl::n10::FORMATS };

fn bit(b: bool) -> Value {
    Value::new(1, b.into())
}

/// A state's `st$*` pins (`texture_unit`'s codes of `TexState` on `rtl::texture_unit::TextureState`;
/// `texture_path`'s `state$*` and the textured `raster_top`'s `tex_state$*` are the same
/// bundle).
pub fn state_pins(s: &TexState) -> Vec<(&'static str, Value)> {
    let code = |w: Wrap| WRAPS.iter().position(|x| *x == w).unwrap() as u128;
    vec![
        ("st$ws", Value::new(4, s.size_log2[0].into())),
        ("st$hs", Value::new(4, s.size_log2[1].into())),
        ("st$levels", Value::new(4, s.levels.into())),
        ("st$base", Value::new(26, s.base.into())),
        ("st$min_linear", bit(s.sampler.min == Filter::Linear)),
        ("st$mag_linear", bit(s.sampler.mag == Filter::Linear)),
        ("st$mip", Value::new(2, MIPS.iter().position(|m| *m == s.sampler.mip).unwrap() as u128)),
        ("st$wrap_s", Value::new(2, code(s.sampler.wrap_s))),
        ("st$wrap_t", Value::new(2, code(s.sampler.wrap_t))),
        ("st$format", Value::new(3, TexelFormat::ALL.iter().position(|f| *f == s.format).unwrap() as u128)),
        ("st$gaussian", bit(s.sampler.weights == Weights::Gaussian)),
        ("st$env", Value::new(3, ENVS.iter().position(|e| *e == s.env).unwrap() as u128)),
    ]
}

/// Triangle `s` on the pins `inp$*`, `tex$*` and `tex_state$*` (an untextured triangle's
/// texture words but `textured` and `mode` are left as they were).
pub fn triangle_pins(s: &Sent) -> Vec<(String, Value)> {
    use rtl::texture_setup::{QB, ST};
    let mut pins = crate::frame::triangle_pins(&BUILD, &s.v);
    let mode = MODES.iter().position(|m| *m == s.blend).expect("a blend mode of rtl::blend") as u128;
    pins.extend([("tex$textured".to_string(), bit(s.tex.is_some())), ("tex$mode".into(), Value::new(3, mode))]);
    if let Some(t) = &s.tex {
        for (k, v) in t.v.iter().enumerate() {
            pins.push((format!("tex$sq{k}"), raw(ST, v.a[0])));
            pins.push((format!("tex$tq{k}"), raw(ST, v.a[1])));
            pins.push((format!("tex$q{k}"), raw(QB, v.a[2])));
        }
        let state = state_pins(&t.state).into_iter();
        pins.extend(state.map(|(n, v)| (format!("tex_state${}", n.strip_prefix("st$").expect("st$ pins")), v)));
    }
    pins
}

/// The outputs [`draw`] reads beside the framebuffer's request ([`REQUEST`]).
pub const READ: [&str; 7] =
    ["done", "inp$ready", "counters$hits", "counters$misses", "counters$fills", "tex_mem$valid", "tex_mem$addr"];

/// A frame drawn by the textured `raster_top`.
pub struct TexturedOut {
    /// The depth and colour buffers.
    pub memory: Memory,
    /// Cycles until `done`: the cycle it was first high.
    pub cycles: u64,
    /// The texture cache's hits, misses and fills then.
    pub counters: [u64; 3],
}

/// One clock of the textured `raster_top` in some simulator: the inputs given (inputs not
/// named keep their value), the outputs sampled before the edge.
pub type Clock<'a> = dyn FnMut(&[(String, Value)]) -> Result<Outputs, String> + 'a;

/// The frame of `tris` on a `width` x `height` screen cleared to `background` through
/// `cycle`, back faces culled when `cull_back`, the textures in `tex` (acknowledging a
/// request when `ack` says, by cycle); giving up after `max_cycles`.
#[allow(clippy::too_many_arguments)]
pub fn draw(
    cycle: &mut Clock,
    tris: &[Sent],
    (width, height): (u32, u32),
    background: [u8; 3],
    cull_back: bool,
    tex: &mut ReadPort,
    ack: &mut dyn FnMut(u64) -> bool,
    max_cycles: u64,
) -> Result<TexturedOut, String> {
    let (dim, depth) = (rtl::n10::widths::DIM, rtl::n10::widths::DEPTH);
    let zmax = model::cull_sort::z_max(&BUILD.formats) as u32;
    let mut memory = Memory::new(BUILD.class, 1, (width, height), zmax, background, ReadDuringWrite::Old);
    let mut next = 0;
    for now in 0..max_cycles {
        let m = tex.answer(now, ack(now));
        let mut pins = vec![
            ("width".to_string(), Value::new(dim, width.into())),
            ("height".into(), Value::new(dim, height.into())),
            ("cull_back".into(), bit(cull_back)),
            ("inp_flush".into(), bit(false)),
            ("inp$valid".into(), bit(next < tris.len())),
            ("inp_last".into(), bit(next + 1 == tris.len())),
            ("mem$ready".into(), bit(true)),
            ("mem$rd_z".into(), memory.rd_z_value(depth)),
            ("mem$rd_rgb".into(), memory.rd_rgb_value()),
            ("tex_mem$ack".into(), bit(m.ack)),
            ("tex_mem$rvalid".into(), bit(m.rvalid)),
            ("tex_mem$rdata".into(), Value::new(32, m.rdata.into())),
        ];
        if let Some(s) = tris.get(next) {
            pins.extend(triangle_pins(s));
        }
        let o = cycle(&pins)?;
        let get = |pin: &str| o.get(pin).to_u128() as u32;
        if get("done") == 1 && next == tris.len() {
            let counters = ["counters$hits", "counters$misses", "counters$fills"].map(|p| u64::from(get(p)));
            return Ok(TexturedOut { memory, cycles: now, counters });
        }
        next += usize::from(next < tris.len() && get("inp$ready") == 1);
        memory.edge(true, &Request::of(&o));
        tex.ask(now, &m, MemAsk { valid: get("tex_mem$valid") == 1, addr: get("tex_mem$addr") });
    }
    Err(format!(
        "raster_top (TEXTURE = 1): no done after {max_cycles} cycles ({next} of {} triangles taken)",
        tris.len()
    ))
}

/// The textured `raster_top` under Verilator (its default parameters).
pub struct TexturedVl {
    vl: VlSim,
}

impl TexturedVl {
    /// Verilates it (cached), the level of detail by GL's exact rho when `exact` (else
    /// 001's eq. 4), and makes a fresh model.
    pub fn new(exact: bool) -> Result<TexturedVl, String> {
        let unit = rtl::Unit::named("raster_top").expect("raster_top is in UNITS");
        let params = unit.params([("TEXTURE".to_owned(), 1), ("EXACT".to_owned(), exact as u64)])?;
        Ok(TexturedVl { vl: crate::verilated(unit, &params, None)?.model()? })
    }

    /// One clock: [`Clock`].
    pub fn cycle(&mut self, pins: &[(String, Value)]) -> Result<Outputs, String> {
        for (pin, v) in pins {
            self.vl.set(pin, v);
        }
        self.vl.settle();
        let o = Outputs(READ.iter().chain(&REQUEST).map(|p| (p.to_string(), self.vl.get(p))).collect());
        self.vl.clock();
        Ok(o)
    }
}
