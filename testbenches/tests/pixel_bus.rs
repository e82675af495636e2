//! `pixel_bus`: rust-hdl and Verilator in lockstep with `model::pixel_bus`, every output
//! compared every cycle, the depth and colour buffers in two `model::word_memory`s (a
//! latency, back-pressure, reads that return a word as it was before any unanswered write).
//! At the end both memories equal `pixel_out::Framebuffer`'s buffers after the same
//! pixels, and nothing was read or written outside the screen.

use model::cull_sort::z_max;
use model::pixel_bus::{color_word, Config, FrameDrive, Inputs, Outputs as ModelOutputs, Params, PixelBus as Model};
use model::pixel_out::Framebuffer;
use model::span::Pixel;
use model::word_memory::WordMemory;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::pixel_bus::{PixelBus, ENTRIES};
use rtl::widths::{DEPTH, DIM, FORMATS, RGB};
use testbenches::streams::{as_pins, pixel};
use testbenches::{count, seed, verilated_with, Dual, Outputs, Value};

const DEPTH_BASE: u32 = 0x10_0000;
const COLOR_BASE: u32 = 0x40_0000;
/// Words before and after each buffer, to catch transfers outside it.
const GUARD: u32 = 16;
/// What the memories hold before a frame.
const FILL: u32 = 0xdead_beef;

/// The memories and the pixels' source around a lockstep run.
#[derive(Clone, Copy)]
struct Pace {
    latency: u32,
    /// Chance that a memory channel holds back a transfer in a cycle.
    stall: f64,
    /// Chance that the source offers the next pixel in a cycle.
    offer: f64,
}

/// The model's build parameters for the RTL's build.
fn params() -> Params {
    Params { entries: ENTRIES as u32, depth_bits: DEPTH as u32 }
}

/// A `width` x `height` screen whose rows are `pad` words longer than the screen, the
/// colour buffer's by one more.
fn config(width: u32, height: u32, pad: u32) -> Config {
    Config {
        width,
        height,
        background: [0x12, 0x34, 0x56],
        color_base: COLOR_BASE,
        color_pitch: (4 * (width + pad + 1)) as u16,
        depth_base: DEPTH_BASE,
        depth_pitch: (4 * (width + pad)) as u16,
    }
}

/// A memory holding a buffer at `base` with rows of `pitch` bytes, and [`GUARD`] words
/// each side, every word [`FILL`].
fn memory<'a>(c: &Config, base: u32, pitch: u16, pace: Pace, rng: &mut ChaCha8Rng) -> WordMemory<'a> {
    let words = c.height * u32::from(pitch) / 4 + 2 * GUARD;
    let mut stall = ChaCha8Rng::seed_from_u64(rng.gen());
    WordMemory::new(vec![FILL; words as usize], base - 4 * GUARD, pace.latency, move || stall.gen_bool(pace.stall))
}

/// Every input of the unit as pins.
fn input_pins(i: &Inputs) -> Vec<(String, Value)> {
    let c = &i.config;
    let bit = |b: bool| Value::new(1, b as u128);
    let mut pins = vec![
        ("start".to_owned(), bit(i.start)),
        ("clear".into(), bit(i.clear)),
        ("width".into(), Value::new(DIM, c.width.into())),
        ("height".into(), Value::new(DIM, c.height.into())),
        ("background".into(), Value::new(RGB, color_word(c.background).into())),
        ("color_base".into(), Value::new(32, c.color_base.into())),
        ("color_pitch".into(), Value::new(16, c.color_pitch.into())),
        ("depth_base".into(), Value::new(32, c.depth_base.into())),
        ("depth_pitch".into(), Value::new(16, c.depth_pitch.into())),
        ("inp$valid".into(), bit(i.pixel.is_some())),
        ("zr$ar_ready".into(), bit(i.depth.ar_ready)),
        ("zr$r_valid".into(), bit(i.depth.r_valid)),
        ("zr$r_data".into(), Value::new(32, i.depth.r_data.into())),
        ("zr$r_resp".into(), Value::new(2, if i.depth.r_error { 2 } else { 0 })),
    ];
    // The pixel's fields are zero while none is offered, as the model assumes.
    pins.extend(pixel("inp", &i.pixel.unwrap_or(Pixel { x: 0, y: 0, z: 0, rgb: [0; 3] })));
    for (bus, r) in [("zw", &i.depth), ("cw", &i.color)] {
        pins.extend([
            (format!("{bus}$aw_ready"), bit(r.aw_ready)),
            (format!("{bus}$w_ready"), bit(r.w_ready)),
            (format!("{bus}$b_valid"), bit(r.b_valid)),
            (format!("{bus}$b_resp"), Value::new(2, if r.b_error { 2 } else { 0 })),
        ]);
    }
    pins
}

/// Every output of the unit against the model's: the handshakes, the transfers offered
/// (their address and data where they are valid) and the constant AXI fields.
fn compare(got: &Outputs, o: &ModelOutputs) -> Result<(), String> {
    let bit = |b: bool| Value::new(1, b as u128);
    let mut want: Vec<(String, Value)> = vec![
        ("inp$ready".into(), bit(o.ready)),
        ("idle".into(), bit(o.idle)),
        ("error".into(), bit(o.error)),
        ("zr$ar_valid".into(), bit(o.depth.ar.is_some())),
        ("zr$ar_len".into(), Value::new(8, 0)),
        ("zr$ar_size".into(), Value::new(3, 2)),
        ("zr$ar_burst".into(), Value::new(2, 1)),
        ("zr$r_ready".into(), bit(true)),
    ];
    if let Some(a) = o.depth.ar {
        want.push(("zr$ar_addr".into(), Value::new(32, a.into())));
    }
    for (bus, q) in [("zw", &o.depth), ("cw", &o.color)] {
        let pin = |f: &str| format!("{bus}${f}");
        want.extend([
            (pin("aw_valid"), bit(q.aw.is_some())),
            (pin("w_valid"), bit(q.w.is_some())),
            (pin("aw_len"), Value::new(8, 0)),
            (pin("aw_size"), Value::new(3, 2)),
            (pin("aw_burst"), Value::new(2, 1)),
            (pin("w_strb"), Value::new(4, 15)),
            (pin("w_last"), bit(true)),
            (pin("b_ready"), bit(true)),
        ]);
        if let Some(a) = q.aw {
            want.push((pin("aw_addr"), Value::new(32, a.into())));
        }
        if let Some(d) = q.w {
            want.push((pin("w_data"), Value::new(32, d.into())));
        }
    }
    match want.iter().find(|(pin, v)| got.get(pin) != v) {
        Some((pin, v)) => Err(format!("{pin}: RTL {}, model {v}", got.get(pin))),
        None => Ok(()),
    }
}

/// The unit beside its Verilog, both just out of reset.
fn dual() -> Dual<PixelBus> {
    let vl = verilated_with("pixel_bus", []);
    Dual::new(PixelBus::new(), vl.model().unwrap_or_else(|e| panic!("{e}")))
}

/// How a frame ended.
struct End {
    cycles: u64,
    error: bool,
}

/// One frame (`drive`'s) through the model and both simulators in lockstep, for at most
/// `limit` cycles; panics on the first difference, and on a transfer outside the memories.
fn lockstep(dual: &mut Dual<PixelBus>, drive: &mut FrameDrive, limit: u64) -> End {
    let mut model = Model::new(params()).expect("the RTL's parameters");
    for cycle in 0..limit {
        let i = drive.inputs();
        let o = model.outputs();
        let got = dual.cycle(&as_pins(&input_pins(&i))).unwrap_or_else(|m| panic!("{m}"));
        compare(&got, &o).unwrap_or_else(|e| panic!("cycle {cycle}: {e}"));
        model.clock(&i);
        if drive.clock(&i, &o) {
            let outside = (drive.depth.outside_reads, drive.depth.outside_writes, drive.color.outside_writes);
            assert_eq!(outside, (0, 0, 0), "reads and writes outside the memories");
            return End { cycles: cycle + 1, error: o.error };
        }
    }
    panic!("the frame did not end in {limit} cycles");
}

/// The memories' words after `pixels` drawn on buffers cleared (or holding [`FILL`]), as
/// `Framebuffer` draws them.
fn expected(c: &Config, clear: bool, pixels: &[Pixel], rng: &mut ChaCha8Rng) -> (Vec<u32>, Vec<u32>) {
    let pace = Pace { latency: 0, stall: 0.0, offer: 1.0 };
    let (mut depth, mut color) =
        (memory(c, DEPTH_BASE, c.depth_pitch, pace, rng), memory(c, COLOR_BASE, c.color_pitch, pace, rng));
    let far = z_max(&FORMATS) as u32;
    let mut fb = Framebuffer::new(c.width, c.height, if clear { far } else { FILL & far }, c.background);
    for p in pixels {
        fb.pixel_out(p, 0);
    }
    for y in 0..c.height {
        for x in 0..c.width {
            let (za, ca) = c.addresses(x, y);
            let i = (y * c.width + x) as usize;
            let (zi, ci) = (depth.slot(za).expect("inside"), color.slot(ca).expect("inside"));
            if clear || fb.written[i] {
                depth.words[zi] = fb.depth[i];
                color.words[ci] = color_word(fb.rgb[i]);
            }
        }
    }
    (depth.words, color.words)
}

/// Random pixels on the screen, a third of them at the address of one of the last few, so
/// that the hazard check and the queue's order are exercised; depths skewed to the edges of
/// the test: equal to that pixel's, the far plane, 0.
fn pixels(rng: &mut ChaCha8Rng, c: &Config, n: usize) -> Vec<Pixel> {
    let far = z_max(&FORMATS) as u32;
    let mut out: Vec<Pixel> = Vec::with_capacity(n);
    for i in 0..n {
        let before = (i > 0).then(|| out[i - rng.gen_range(1..=20).min(i)]);
        let (x, y) = match before {
            Some(p) if rng.gen_bool(0.3) => (p.x, p.y),
            _ => (rng.gen_range(0..c.width), rng.gen_range(0..c.height)),
        };
        let z = match (rng.gen_range(0..6), before) {
            (0, Some(p)) => p.z,
            (1, _) => far,
            (2, _) => 0,
            _ => rng.gen_range(0..=far),
        };
        out.push(Pixel { x, y, z, rgb: rng.gen() });
    }
    out
}

/// Frames of random pixels at latencies 0 to 40, with and without back-pressure and gaps
/// in the pixels, the clear on and off, rows padded: every output as the model's, every
/// cycle, and the buffers as `Framebuffer`'s.
#[test]
fn pixel_bus_random_frames_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let paces = [
        Pace { latency: 0, stall: 0.0, offer: 1.0 },
        Pace { latency: 2, stall: 0.3, offer: 0.8 },
        Pace { latency: 20, stall: 0.5, offer: 0.6 },
        Pace { latency: 40, stall: 0.0, offer: 1.0 },
    ];
    for (k, pace) in paces.into_iter().enumerate() {
        let c = config(rng.gen_range(1..24), rng.gen_range(1..16), rng.gen_range(0..3));
        let clear = k % 2 == 0;
        let ps = pixels(&mut rng, &c, count() / 2);
        let mut depth = memory(&c, DEPTH_BASE, c.depth_pitch, pace, &mut rng);
        let mut color = memory(&c, COLOR_BASE, c.color_pitch, pace, &mut rng);
        let mut offer = ChaCha8Rng::seed_from_u64(rng.gen());
        let mut drive = FrameDrive::new(c, clear, &mut depth, &mut color, &ps, move || offer.gen_bool(pace.offer));
        let limit = 100 + u64::from(4 * c.width * c.height) + ps.len() as u64 * (2 * u64::from(pace.latency) + 20);
        let end = lockstep(&mut dual(), &mut drive, limit);
        let (z, rgb) = expected(&c, clear, &ps, &mut rng);
        assert!(!end.error);
        assert_eq!(depth.words, z, "seed {seed}, latency {}: depth", pace.latency);
        assert_eq!(color.words, rgb, "seed {seed}, latency {}: colour", pace.latency);
    }
}

/// The last row of the build's largest screen, a pixel a cycle at latency 0, with the depth
/// buffer's rows at the largest pitch (65,532 bytes): `y * pitch` uses every bit of the
/// multipliers. The memories hold the last two rows only (the buffers' bases are moved down
/// by the rows before them; the depth buffer's wraps below address 0, as 32-bit addresses
/// do).
#[test]
fn pixel_bus_largest_screen_vs_model() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let side = 1u32 << rtl::widths::SCREEN;
    let (z_pitch, c_pitch) = (0xfffc_u16, (4 * side) as u16);
    let skip = |pitch: u16| (side - 2) * u32::from(pitch);
    let c = Config {
        width: side,
        height: side,
        background: [1, 2, 3],
        color_base: COLOR_BASE.wrapping_sub(skip(c_pitch)),
        color_pitch: c_pitch,
        depth_base: DEPTH_BASE.wrapping_sub(skip(z_pitch)),
        depth_pitch: z_pitch,
    };
    let ps: Vec<Pixel> = (0..side).map(|x| Pixel { x, y: side - 1, z: x, rgb: [x as u8, 1, 2] }).collect();
    let pace = Pace { latency: 0, stall: 0.0, offer: 1.0 };
    let window = Config { height: 2, ..c };
    let mut depth = memory(&window, DEPTH_BASE, z_pitch, pace, &mut rng);
    let mut color = memory(&window, COLOR_BASE, c_pitch, pace, &mut rng);
    let end = lockstep(&mut dual(), &mut FrameDrive::new(c, false, &mut depth, &mut color, &ps, || true), 10 * 1024);
    // A pixel a cycle from cycle 1, each a cycle in the input registers, then the last
    // one's read, test, write and response (derived in the model's test at latency 0).
    assert_eq!((end.cycles, end.error), (u64::from(side) + 8, false));
    // Every pixel is nearer than the fill's depth, so each is written.
    let row = |pitch: u16| (GUARD + u32::from(pitch) / 4) as usize;
    for x in 0..side {
        assert_eq!(depth.words[row(z_pitch) + x as usize], x, "depth at x {x}");
        assert_eq!(color.words[row(c_pitch) + x as usize], color_word([x as u8, 1, 2]), "colour at x {x}");
    }
    assert_eq!((depth.written.len(), color.written.len()), (side as usize, side as usize));
}
