//! The shading engine (paper 000): rust-hdl and Verilator in lockstep against the
//! cycle-exact `model::se::Se`, every output every clock; and the z compare (Fig. 10).

use model::se::array::{engine_params, spans};
use model::se::{interp::interp, line_through, mul::endpoint, zcmp, Se, SeCmd, SeIn, SeOut, SeParams, PORTS};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::se::zcmp::Zcmp;
use rtl::se::{Se8, SePaper, SeWide};
use rust_hdl::prelude::*;
use std::time::Instant;
use testbenches::{count, seed, target_dir, write_if_changed, Dual, Mismatch, Outputs, Pins, Value, Verilated};

/// 000 Fig. 11: region (0, 64), span (2, 9), z 0x010 -> 0x3FF, R 0 -> 7, G 7 -> 0, B 3 -> 0.
const FIG11_SPAN: (i128, i128) = (2, 9);
const FIG11_ENDS: [(i128, i128); 4] = [(0x010, 0x3ff), (0, 7), (7, 0), (3, 0)];
/// The printed outputs for x = 2..9 (R read as 0, 1, 2, ..., 7: the printed "0, 2, 2" fits
/// no straight line, see the papers' digest).
const FIG11_Z: [u64; 8] = [0x010, 0x0a0, 0x12f, 0x1bf, 0x24f, 0x2df, 0x36f, 0x3ff];
const FIG11_R: [u64; 8] = [0, 1, 2, 3, 4, 5, 6, 7];
const FIG11_G: [u64; 8] = [7, 6, 5, 4, 3, 2, 1, 0];
const FIG11_B: [u64; 8] = [3, 3, 2, 2, 1, 1, 1, 0];

/// The emitted SE with `params` over the defaults (the committed `hdl-out/se.v` for 000's).
fn verilog(params: &[(&str, u64)]) -> Verilated {
    let unit = rtl::Unit::named("se").expect("se is in UNITS");
    let given = params.iter().map(|(k, v)| (k.to_string(), *v));
    let e = unit.emit(&unit.params(given).expect("se's parameters")).expect("supported parameters");
    testbenches::verilate(&e).unwrap_or_else(|e| panic!("{e}"))
}

/// A two's complement value as a `width`-bit port value.
fn word(v: i128, width: usize) -> Value {
    Value::new(width, v as u128 & ((1u128 << width) - 1))
}

/// The model's outputs of one clock as the pins' values.
fn pins(o: &SeOut, prm: &SeParams) -> Vec<(String, Value)> {
    let (zw, cw, ab) = (prm.zw as usize, prm.cw as usize, (prm.levels() - 2) as usize);
    let bit = |b: bool| Value::new(1, b as u128);
    let mut v = vec![
        ("ready".to_owned(), bit(o.ready)),
        ("oz_rd".to_owned(), bit(o.oz_rd)),
        ("oz_addr".to_owned(), Value::new(ab, o.oz_addr as u128)),
        ("wr".to_owned(), bit(o.wr)),
        ("wr_addr".to_owned(), Value::new(ab, o.wr_addr as u128)),
    ];
    for k in 0..PORTS {
        v.push((format!("nz{k}"), Value::new(zw, o.nz[k] as u128)));
        for (ch, name) in ["r", "g", "b"].iter().enumerate() {
            v.push((format!("{name}{k}"), Value::new(cw, o.c[ch][k] as u128)));
        }
        v.push((format!("we{k}"), bit(o.we[k])));
    }
    v
}

/// The inputs of one clock as the pins' values.
fn input_pins(i: &SeIn, prm: &SeParams) -> Vec<(&'static str, Value)> {
    let xw = model::se::SPAN_X_BITS as usize;
    let mut v = vec![("valid", Value::new(1, i.valid as u128)), ("xl", word(i.cmd.xl, xw)), ("xr", word(i.cmd.xr, xw))];
    for (j, (a, b)) in [("za", "zb"), ("ra", "rb"), ("ga", "gb"), ("ba", "bb")].into_iter().enumerate() {
        let w = prm.ab_bits(j) as usize;
        v.push((a, word(i.cmd.a[j], w)));
        v.push((b, word(i.cmd.b[j], w)));
    }
    for (pin, oz) in ["oz0", "oz1", "oz2", "oz3"].into_iter().zip(i.oz) {
        v.push((pin, Value::new(prm.zw as usize, oz as u128)));
    }
    v
}

/// One pixel written by the engine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Write {
    row: u32,
    x: u32,
    z: u64,
    c: [u64; 3],
}

/// The engine in both simulators and the model, against a z-buffer of `rows` rows of the
/// engine's P pixels.
struct Bench<U> {
    dual: Dual<U>,
    model: Se,
    prm: SeParams,
    zbuf: Vec<Vec<u64>>,
    /// Rows of the spans accepted and not yet written out.
    pending: std::collections::VecDeque<u32>,
    writes: Vec<Write>,
}

impl<U: Block + Pins> Bench<U> {
    /// `unit`, the rust-hdl engine with parameters `prm`, beside `vl`, its Verilog.
    fn new(unit: U, prm: SeParams, vl: &Verilated, rows: usize, z0: u64) -> Self {
        let dual = Dual::new(unit, vl.model().unwrap_or_else(|e| panic!("{e}")));
        Bench {
            dual,
            model: Se::new(prm),
            prm,
            zbuf: vec![vec![z0; prm.p as usize]; rows],
            pending: Default::default(),
            writes: Vec::new(),
        }
    }

    /// One clock, offering `span` (row, command) if any; returns whether it was taken.
    fn clock(&mut self, span: Option<(u32, &SeCmd)>) -> Result<bool, Mismatch> {
        let prm = self.prm;
        let before = self.model.outputs();
        let cmd = span.map_or(SeCmd::default(), |s| *s.1);
        let mut i = SeIn { valid: span.is_some(), cmd, oz: [0; PORTS] };
        if before.oz_rd {
            let row = *self.pending.back().expect("a load follows an accept") as usize;
            let at = 4 * before.oz_addr as usize;
            i.oz.copy_from_slice(&self.zbuf[row][at..at + PORTS]);
        }
        let got: Outputs = self.dual.cycle(&input_pins(&i, &prm))?;
        let want = self.model.step(&i);
        for (pin, v) in pins(&want, &prm) {
            self.dual.expect(&got, &pin, &v)?;
        }
        let taken = want.ready && i.valid;
        if let (true, Some((row, _))) = (taken, span) {
            self.pending.push_back(row);
        }
        if want.wr {
            let row = *self.pending.front().expect("a write follows an accept");
            for k in 0..PORTS {
                let x = 4 * want.wr_addr + k as u32;
                if want.we[k] {
                    self.zbuf[row as usize][x as usize] = want.nz[k];
                    self.writes.push(Write { row, x, z: want.nz[k], c: std::array::from_fn(|ch| want.c[ch][k]) });
                }
            }
            if want.wr_addr == prm.p / 4 - 1 {
                self.pending.pop_front();
            }
        }
        Ok(taken)
    }

    /// Offers each span until taken (with `gap(k)` idle clocks before span k), then runs
    /// until the engine is idle.
    fn run(&mut self, spans: &[(u32, SeCmd)], mut gap: impl FnMut(usize) -> u32) -> Result<(), Mismatch> {
        for (k, (row, cmd)) in spans.iter().enumerate() {
            for _ in 0..gap(k) {
                self.clock(None)?;
            }
            while !self.clock(Some((*row, cmd)))? {}
        }
        while !self.model.idle() {
            self.clock(None)?;
        }
        Ok(())
    }
}

/// A span command through (xl, v0) .. (xr, v1) for each attribute (values in word LSBs).
fn through(xl: i128, xr: i128, ends: &[(i128, i128); 4], frac: u32) -> SeCmd {
    let lines: [(i128, i128); 4] = std::array::from_fn(|j| line_through(xl, ends[j].0, xr, ends[j].1, frac));
    SeCmd { xl, xr, a: lines.map(|l| l.0), b: lines.map(|l| l.1) }
}

#[test]
fn se_paper_000_fig11() {
    let vl = verilog(&[]);
    let mut b = Bench::new(SePaper::new(0), SeParams::paper(0), &vl, 1, 0xff_ffff);
    let (xl, xr) = FIG11_SPAN;
    let cmd = through(xl, xr, &FIG11_ENDS, b.prm.frac);
    // The ends the multipliers round to (the papers' digest: z -272 and 8935).
    assert_eq!((endpoint(cmd.a[0], cmd.b[0], 0, 24, 16), endpoint(cmd.a[0], cmd.b[0], 64, 24, 16)), (-272, 8935));
    let start = Instant::now();
    b.run(&[(0, cmd)], |_| 0).unwrap_or_else(|m| panic!("{m}"));
    let cycles = b.dual.cycles();
    let xs: Vec<u32> = b.writes.iter().map(|w| w.x).collect();
    assert_eq!(xs, (2..=9).collect::<Vec<u32>>(), "written pixels");
    let col = |f: fn(&Write) -> u64| b.writes.iter().map(f).collect::<Vec<u64>>();
    assert_eq!(col(|w| w.z), FIG11_Z, "z");
    assert_eq!(col(|w| w.c[0]), FIG11_R, "R");
    assert_eq!(col(|w| w.c[1]), FIG11_G, "G");
    assert_eq!(col(|w| w.c[2]), FIG11_B, "B");
    // Accepted in clock 0, last write in clock latency - 1, then idle.
    assert_eq!(cycles, b.prm.latency() as u64, "clocks of one span");
    eprintln!("se_paper_000_fig11: {cycles} clocks in {:.2?} (both simulators and the model)", start.elapsed());
}

/// The new z the engine computes for `cmd` at pixel x of engine `prm` (a zw-bit word).
fn new_z(cmd: &SeCmd, prm: &SeParams, x: usize) -> u64 {
    let (xl, xr) = prm.region();
    let e = |at| endpoint(cmd.a[0], cmd.b[0], at, prm.zw, prm.frac);
    interp(e(xl), e(xr), prm.p)[x] as u64 & ((1 << prm.zw) - 1)
}

/// A random span for engine `prm`: ends inside its region, across either edge, wholly
/// outside or crossed (Xl > Xr), anywhere in the 13-bit column range; lines through random
/// ends of either sign at the region's ends, a tenth of them overflowing the words (the
/// engine wraps them; the model must too).
fn random_span(rng: &mut ChaCha8Rng, prm: &SeParams) -> SeCmd {
    let (lo, hi) = prm.region();
    let x = |rng: &mut ChaCha8Rng| -> i128 {
        match rng.gen_range(0..8) {
            0 => rng.gen_range(-4096..4096),
            1 => [lo - 1, lo, hi - 1, hi][rng.gen_range(0..4)],
            2 => rng.gen_range(lo - 70..lo),
            3 => rng.gen_range(hi..hi + 70),
            _ => rng.gen_range(lo..hi),
        }
    };
    let (mut xl, mut xr) = (x(rng), x(rng));
    if rng.gen_bool(0.85) && xl > xr {
        std::mem::swap(&mut xl, &mut xr);
    }
    let mut cmd = SeCmd { xl, xr, ..SeCmd::default() };
    for j in 0..4 {
        let big = 1i128 << (prm.width(j) - 1);
        let end = |rng: &mut ChaCha8Rng| {
            if rng.gen_bool(0.1) {
                rng.gen_range(-8 * big..8 * big)
            } else {
                rng.gen_range(-big..big)
            }
        };
        let (v0, v1, f) = (end(rng), end(rng), prm.frac);
        // f(XL_i) = v0 and f(XR_i) = v1, give or take random fraction bits.
        cmd.a[j] = ((v1 - v0) << f) / prm.p as i128 + rng.gen_range(-64..64);
        cmd.b[j] = (v0 << f) - lo * cmd.a[j] + rng.gen_range(0..1 << f);
    }
    cmd
}

/// Old z for a span's pixels: the new z minus 1 (hidden), equal (hidden: LESS), plus 1
/// (visible), far, or random.
fn old_z(rng: &mut ChaCha8Rng, cmd: &SeCmd, prm: &SeParams) -> Vec<u64> {
    let max = (1u64 << prm.zw) - 1;
    (0..prm.p as usize)
        .map(|x| {
            let z = new_z(cmd, prm, x);
            match rng.gen_range(0..5) {
                0 => z.saturating_sub(1),
                1 => z,
                2 => (z + 1).min(max),
                3 => max,
                _ => rng.gen_range(0..=max),
            }
        })
        .collect()
}

/// `n` random spans for `unit` (parameters `prm`, Verilog `vl`), mostly back to back (a new
/// one offered in the clock `ready` comes back), some after idle gaps, with old z hidden,
/// equal and visible; every output of both simulators against the model every clock.
fn random_spans<U: Block + Pins>(unit: U, prm: SeParams, vl: &Verilated, n: usize) {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ prm.p as u64 ^ (prm.index as u64) << 8);
    const ROWS: u32 = 3;
    let mut b = Bench::new(unit, prm, vl, ROWS as usize, 0);
    let p = prm.p as usize;
    let spans: Vec<(u32, SeCmd)> = (0..n).map(|k| (k as u32 % ROWS, random_span(&mut rng, &prm))).collect();
    let olds: Vec<Vec<u64>> = spans.iter().map(|(_, c)| old_z(&mut rng, c, &prm)).collect();
    let gaps: Vec<u32> = (0..n).map(|_| if rng.gen_bool(0.2) { rng.gen_range(1..200) } else { 0 }).collect();
    // The cases the test is for, counted over the stimulus.
    let (lo, hi) = (0, prm.p as i128 - 1);
    let z_ends = |c: &SeCmd| [0, prm.p as i128].map(|x| endpoint(c.a[0], c.b[0], x, prm.zw, prm.frac));
    let cases = [
        (
            "z ends of both signs",
            spans.iter().filter(|(_, c)| z_ends(c)[0].signum() * z_ends(c)[1].signum() < 0).count(),
        ),
        ("crossed (Xl > Xr)", spans.iter().filter(|(_, c)| c.xl > c.xr).count()),
        ("wholly outside", spans.iter().filter(|(_, c)| c.xl <= c.xr && (c.xr < lo || c.xl > hi)).count()),
        (
            "partly outside",
            spans.iter().filter(|(_, c)| c.xl <= c.xr && c.xl <= hi && c.xr >= lo && (c.xl < lo || c.xr > hi)).count(),
        ),
        (
            "pixels hidden (new z > old z)",
            (0..n).map(|k| (0..p).filter(|&x| new_z(&spans[k].1, &prm, x) > olds[k][x]).count()).sum(),
        ),
        (
            "pixels equal (new z = old z)",
            (0..n).map(|k| (0..p).filter(|&x| new_z(&spans[k].1, &prm, x) == olds[k][x]).count()).sum(),
        ),
        (
            "pixels visible (new z < old z)",
            (0..n).map(|k| (0..p).filter(|&x| new_z(&spans[k].1, &prm, x) < olds[k][x]).count()).sum(),
        ),
        ("back to back", gaps.iter().filter(|g| **g == 0).count()),
    ];
    for (what, count) in cases {
        assert!(n < 100 || count > 0, "seed {seed}: the stimulus has no case '{what}'");
    }
    // Each span's old z is set in its row when it is first offered; its row's last span
    // (three before) has written out by then.
    let start = Instant::now();
    let mut taken = 0;
    for (k, (row, cmd)) in spans.iter().enumerate() {
        let run = |b: &mut Bench<U>| -> Result<(), Mismatch> {
            for _ in 0..gaps[k] {
                b.clock(None)?;
            }
            b.zbuf[*row as usize].clone_from(&olds[k]);
            while !b.clock(Some((*row, cmd)))? {}
            Ok(())
        };
        run(&mut b).unwrap_or_else(|m| panic!("{m}\nseed {seed}: span {k}: {cmd:?}"));
        taken += 1;
    }
    while !b.model.idle() {
        b.clock(None).unwrap_or_else(|m| panic!("{m}\nseed {seed}: draining"));
    }
    let cycles = b.dual.cycles();
    let secs = start.elapsed().as_secs_f64();
    assert_eq!(taken, n);
    assert!(b.writes.len() > n, "seed {seed}: some pixels must be written");
    eprintln!(
        "se random spans, P = {} engine {}: {n} spans ({cases:?}), {cycles} clocks, {} writes in {secs:.1} s: {:.0} clocks/s (rust-hdl, Verilator and the model in lockstep)",
        prm.p,
        prm.index,
        b.writes.len(),
        cycles as f64 / secs
    );
}

/// A quarter of `EDGEPAINT_N` spans (250; the soak's random step 2,500): 1,000 spans through
/// rust-hdl's simulation of the whole engine were the test command's longest test (54 s).
#[test]
fn se_random_spans_vs_model() {
    random_spans(SePaper::new(0), SeParams::paper(0), &verilog(&[]), (count() / 4).max(10));
}

/// The last engine of a 1024-pixel row (I = 15: XL_i = 960, XR_i = 1024, X's 11th bit).
#[test]
fn se_engine_15_random_spans_vs_model() {
    random_spans(SePaper::new(15), SeParams::paper(15), &verilog(&[("I", 15)]), (count() / 10).max(10));
}

/// The smallest region the engine is built for (P = 8: 3 levels, 2 port groups).
#[test]
fn se_p8_random_spans_vs_model() {
    let prm = SeParams { p: 8, ..SeParams::paper(0) };
    random_spans(Se8::<24, 16, 40, 32>::new(0), prm, &verilog(&[("P", 8)]), (count() / 4).max(10));
}

/// Spans of the shipped scenes, as the span backend converts them, on the engine it draws
/// with (`SeWide`: z and colour words of 29 and 21 bits), back to back against a z-buffer
/// cleared to far. Each is moved by whole regions into engine 0's (Xl, Xr less 64 m, B plus
/// 64 m A: the multipliers see the same line at the same region ends as engine m's).
#[test]
fn se_scene_spans_vs_model() {
    let prm = SeParams { zw: 29, cw: 21, ..SeParams::paper(0) };
    let vl = verilog(&[("ZW", 29), ("CW", 21)]);
    let per_scene = (count() / 30).max(4);
    let mut all = Vec::new();
    let mut rows = 0;
    for name in ["cube", "sphere", "torus", "pawn", "clip", "all"] {
        let sc = scene::Scene::load(&scene::shipped::path(name)).unwrap();
        let list = sc.to_trilist().unwrap();
        let f = fx::Formats::for_resolution(list.width, list.height);
        let cull = if sc.cull_back { model::cull_sort::Cull::Back } else { model::cull_sort::Cull::None };
        assert_eq!(engine_params(&f), prm, "{name}: the backend's engines");
        let (sp, _) = spans(&list, &f, cull, prm.frac);
        // Spread over the scene: every k-th span.
        let step = (sp.len() / per_scene).max(1);
        for s in sp.iter().step_by(step).take(per_scene) {
            let shift = s.cmd.xl.max(0) / 64 * 64;
            let mut cmd = s.cmd;
            (cmd.xl, cmd.xr) = (cmd.xl - shift, cmd.xr - shift);
            cmd.b = std::array::from_fn(|j| cmd.b[j] + shift * cmd.a[j]);
            all.push((s.y + rows, cmd));
        }
        rows += list.height;
    }
    let mut b = Bench::new(SeWide::new(0), prm, &vl, rows as usize, (1 << 16) - 1);
    b.run(&all, |_| 0).unwrap_or_else(|m| panic!("{m}"));
    assert!(b.writes.len() > all.len(), "the spans cover pixels");
    eprintln!(
        "se_scene_spans_vs_model: {} spans, {} clocks, {} pixels written",
        all.len(),
        b.dual.cycles(),
        b.writes.len()
    );
}

/// The z compare alone (000 Fig. 10) in both simulators: every pair of 4-bit and of
/// 8-bit operands, from either stale flag; the flag equals `model::se::zcmp` and `<`.
/// The literal reading of the text would call 0b10 < 0b01; the RTL does not.
#[test]
fn zcmp_exhaustive_w4_w8() {
    let mut u = Zcmp::default();
    u.connect_all();
    let (ports, text) = (rtl::emit::ports(&u), rtl::emit::verilog("zcmp", &u));
    let file = write_if_changed(&target_dir().join("hdl").join("zcmp"), "zcmp.v", &text).expect("zcmp.v");
    let vl = Verilated::new("zcmp", &file, &ports).unwrap_or_else(|e| panic!("{e}"));
    let mut dual = Dual::new(Zcmp::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let bit = |b: bool| Value::new(1, b as u128);
    let mut compare = |nz: u64, oz: u64, w: u32| -> Result<bool, Mismatch> {
        for i in 0..w {
            let (n, o) = ((nz >> i) & 1 == 1, (oz >> i) & 1 == 1);
            dual.cycle(&[("first", bit(i == 0)), ("nz", bit(n)), ("oz", bit(o))])?;
        }
        let out = dual.cycle(&[("first", bit(false))])?;
        let closer = out.get("closer").bit(0);
        dual.expect(&out, "closer", &bit(zcmp::zcmp(nz, oz, w)))?;
        Ok(closer)
    };
    for w in [4, 8] {
        for nz in 0..1u64 << w {
            for oz in 0..1u64 << w {
                let closer = compare(nz, oz, w).unwrap_or_else(|m| panic!("{m}\nw={w} nz={nz:#b} oz={oz:#b}"));
                assert_eq!(closer, nz < oz, "w={w} nz={nz:#b} oz={oz:#b}");
            }
        }
    }
    assert!(!compare(0b10, 0b01, 2).unwrap(), "the RTL: 2 is not nearer than 1");
    assert!(zcmp::run(zcmp::step_literal, 0b10, 0b01, 2, false), "the literal reading: 2 'nearer' than 1");
}

/// Each simulator alone, stepped through the same clocks (random spans back to back,
/// random old z), at its own speed; each one's outputs must hash like the model's. Prints
/// clocks per second: rust-hdl stepped directly, Verilator in-process (`sim::verilator`), the model.
#[test]
fn se_simulators_alone_agree_and_their_speed() {
    use testbenches::{HdlSim, Sim};
    let prm = SeParams::paper(0);
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let n = (count() / 20).max(5);
    let hash = |h: u64, pins: &[(String, Value)]| pins.iter().fold(h, |h, (_, v)| h.rotate_left(7) ^ v.words()[0]);
    // The clocks: n spans offered back to back, then idle until the engine is.
    let mut model = Se::new(prm);
    let mut clocks: Vec<SeIn> = Vec::new();
    let mut taken = 0;
    while taken < n || !model.idle() {
        let oz = std::array::from_fn(|_| rng.gen_range(0..1 << prm.zw));
        let i = SeIn { valid: taken < n, cmd: random_span(&mut rng, &prm), oz };
        taken += (model.step(&i).ready && i.valid) as usize;
        clocks.push(i);
    }
    let start = Instant::now();
    let mut model = Se::new(prm);
    let want = clocks.iter().fold(0, |h, i| hash(h, &pins(&model.step(i), &prm)));
    let model_speed = clocks.len() as f64 / start.elapsed().as_secs_f64();
    let outs: Vec<String> = pins(&SeOut::default(), &prm).into_iter().map(|(p, _)| p).collect();
    let run = |sim: &mut dyn Sim| -> (u64, f64) {
        let start = Instant::now();
        let mut h = 0;
        for i in &clocks {
            for (pin, v) in input_pins(i, &prm) {
                sim.set(pin, &v);
            }
            sim.settle();
            let got: Vec<(String, Value)> = outs.iter().map(|p| (p.clone(), sim.get(p))).collect();
            h = hash(h, &got);
            sim.clock();
        }
        (h, clocks.len() as f64 / start.elapsed().as_secs_f64())
    };
    let (h_hdl, hdl_speed) = run(&mut HdlSim::new(SePaper::new(0)));
    let vl = verilog(&[]);
    let (h_vl, vl_speed) = run(&mut vl.model().unwrap_or_else(|e| panic!("{e}")));
    assert_eq!(h_hdl, want, "rust-hdl alone differs from the model");
    assert_eq!(h_vl, want, "Verilator alone differs from the model");
    eprintln!(
        "se simulation speed over {} clocks: rust-hdl {hdl_speed:.0} clocks/s, Verilator {vl_speed:.0} clocks/s (both with pins set and read by name), model {model_speed:.0} clocks/s",
        clocks.len()
    );
}
