//! The pixel output unit: rust-hdl and Verilator in lockstep, every cycle, with the depth
//! and colour buffers in Rust (`testbenches::memory`), against
//! `model::pixel_out::Framebuffer`: the same writes in the same order, each `LATENCY`
//! cycles of a ready memory after its pixel came in, and the same buffers at the end; and
//! likewise for chunks of four pixels (`LANES = 4`).

use model::cull_sort::z_max;
use model::pixel_out::{Framebuffer, II, LATENCY};
use model::span::Pixel;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::pixel_out::{ChunkOut, PixelOut};
use rtl::switch::Parts;
use rtl::widths::{ADDR, CLASS, DEPTH, RGB, SCREEN};
use rust_hdl::prelude::Block;
use std::collections::VecDeque;
use testbenches::memory::{pack, Memory, ReadDuringWrite, Request, Write};
use testbenches::streams::{as_pins, pixel, PinValues};
use testbenches::{count, seed, verilated, verilated_with, Dual, Pins, Value};

/// Random pixels on a `w` x `h` screen, skewed toward read-after-write hazards: a pixel
/// often repeats the address of one 1, 2 or 3 pixels before it, with a nearer, farther or
/// equal depth.
fn pixels(rng: &mut ChaCha8Rng, w: u32, h: u32, n: usize, zmax: u32) -> Vec<Pixel> {
    let mut out: Vec<Pixel> = Vec::with_capacity(n);
    for i in 0..n {
        let back = rng.gen_range(1..=4);
        let (x, y) = if i >= back && rng.gen_bool(0.5) {
            (out[i - back].x, out[i - back].y)
        } else {
            (rng.gen_range(0..w), rng.gen_range(0..h))
        };
        let z = match rng.gen_range(0..4) {
            0 if i >= back => out[i - back].z,
            1 => [0, zmax, zmax - 1][rng.gen_range(0..3)],
            _ => rng.gen_range(0..=zmax),
        };
        out.push(Pixel { x, y, z, rgb: rng.gen() });
    }
    out
}

/// A `w` x `h` memory of one pixel a word (`testbenches::memory`, read-during-write `rdw`)
/// and the model's framebuffer, both cleared to `background` at the farthest depth.
pub(crate) fn buffers((w, h): (u32, u32), background: [u8; 3], rdw: ReadDuringWrite) -> (Memory, Framebuffer) {
    let zmax = z_max(&rtl::widths::FORMATS) as u32;
    (Memory::new(CLASS, 1, (w, h), zmax, background, rdw), Framebuffer::new(w, h, zmax, background))
}

/// The lockstep run of a one-lane unit (`PixelOut`, `PixelOutBlend`) on `n` pixels behind
/// `mem`: sends them in order (`inp$valid` low 20% of the time), pixel `i`'s fields and any
/// read data besides `mem$rd_z` on the pins `pins(i, &mem)`, with the memory ready when
/// `ready` says; checks that `inp$ready` is `mem$ready`, the read asked each cycle
/// (`read_ok(&request, i, inp$valid)`, an error saying what is wrong), every write the
/// memory performs against the model's (`model(&mut fb, i)`: pixel `i`'s write, None when
/// its depth test fails), in order, each `LATENCY` ready cycles after its pixel came in, and
/// the buffers at the end against `fb`'s. Returns the memory.
pub(crate) fn lockstep<U: Block + Pins>(
    dual: &mut Dual<U>,
    n: usize,
    (mut mem, mut fb): (Memory, Framebuffer),
    mut ready: impl FnMut(&mut ChaCha8Rng) -> bool,
    pins: impl Fn(usize, &Memory) -> PinValues,
    read_ok: impl Fn(&Request, usize, bool) -> Result<(), String>,
    mut model: impl FnMut(&mut Framebuffer, usize) -> Option<Write>,
) -> Result<Memory, String> {
    assert_eq!(II, 1);
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    // Pixels taken and not yet due: the ready cycle their write is due in, and the
    // model's write (None when the depth test fails).
    let mut due: VecDeque<(u64, Option<Write>)> = VecDeque::new();
    let (mut next, mut ready_cycle) = (0, 0u64);
    while next < n || !due.is_empty() {
        let mem_ready = ready(&mut rng);
        let valid = next < n && rng.gen_bool(0.8);
        let i = next.min(n - 1);
        let mut inputs = vec![
            ("inp$valid", Value::new(1, valid as u128)),
            ("mem$ready", Value::new(1, mem_ready as u128)),
            ("mem$rd_z", mem.rd_z_value(DEPTH)),
        ];
        let own = pins(i, &mem);
        inputs.extend(as_pins(&own));
        let out = dual.cycle(&inputs).map_err(|m| m.to_string())?;
        let cycle = dual.cycles() - 1;
        if (out.get("inp$ready") == &Value::new(1, 1)) != mem_ready {
            return Err(format!("cycle {cycle}: inp$ready differs from mem$ready"));
        }
        let req = Request::of(&out);
        read_ok(&req, i, valid).map_err(|e| format!("cycle {cycle}: {e}"))?;
        let writes = mem.edge(mem_ready, &req);
        let write = writes.as_slice().first().copied();
        if !mem_ready {
            if write.is_some() {
                return Err(format!("cycle {cycle}: a write without mem_ready"));
            }
            continue;
        }
        let want = match due.front() {
            Some(&(at, w)) if at == ready_cycle => {
                due.pop_front();
                w
            }
            _ => None,
        };
        if write != want {
            return Err(format!("cycle {cycle} (ready cycle {ready_cycle}): wrote {write:?}, model {want:?}"));
        }
        if valid {
            due.push_back((ready_cycle + LATENCY as u64, model(&mut fb, next)));
            next += 1;
        }
        ready_cycle += 1;
    }
    if let Some(d) = mem.differs_from(&fb) {
        return Err(format!("the buffers differ from the model's: {d}"));
    }
    Ok(mem)
}

/// Sends `pixels` through [`lockstep`] (the buffers cleared to [7, 8, 9]), with a depth
/// read for each pixel when `depth_test` (a unit with its depth test) and never otherwise;
/// returns the memory and the cycles.
fn run(
    dual: &mut Dual<PixelOut>,
    depth_test: bool,
    pixels: &[Pixel],
    size: (u32, u32),
    rdw: ReadDuringWrite,
    ready: impl FnMut(&mut ChaCha8Rng) -> bool,
) -> Result<(Memory, u64), String> {
    let mem = lockstep(
        dual,
        pixels.len(),
        buffers(size, [7, 8, 9], rdw),
        ready,
        |i, _| pixel("inp", &pixels[i]),
        |req, _, valid| match req.rd_en == (valid && depth_test) as u8 {
            true => Ok(()),
            false => Err(format!("rd_en {} for inp$valid {valid}", req.rd_en)),
        },
        |fb, i| {
            let p = &pixels[i];
            fb.pixel_out(p, 0).then_some(Write { x: p.x, y: p.y, z: p.z, rgb: p.rgb })
        },
    )?;
    Ok((mem, dual.cycles()))
}

fn dual(vl: &testbenches::Verilated) -> Dual<PixelOut> {
    Dual::new(PixelOut::default(), vl.model().unwrap_or_else(|e| panic!("{e}")))
}

/// Random pixels with many hazards, the memory always ready, either read-during-write
/// behaviour: every write LATENCY cycles after its pixel, the buffers equal to the model's.
#[test]
fn pixel_out_random_vs_model() {
    let seed = seed();
    let zmax = z_max(&rtl::widths::FORMATS) as u32;
    let vl = verilated("pixel_out");
    for (i, (size, rdw)) in
        [((7, 5), ReadDuringWrite::Old), ((7, 5), ReadDuringWrite::New), ((64, 48), ReadDuringWrite::Old)]
            .into_iter()
            .enumerate()
    {
        let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(i as u64));
        let px = pixels(&mut rng, size.0, size.1, count() * 4, zmax);
        let (mem, _) =
            run(&mut dual(&vl), true, &px, size, rdw, |_| true).unwrap_or_else(|e| panic!("seed {seed}, {rdw:?}: {e}"));
        assert!(mem.writes > 0 && mem.writes < px.len() as u64, "some pixels pass, some fail");
    }
}

/// The memory port stalled (`mem$ready` low 30% of the time and in bursts): the unit
/// holds everything, nothing is lost or written twice.
#[test]
fn pixel_out_memory_stalled_vs_model() {
    let seed = seed();
    let zmax = z_max(&rtl::widths::FORMATS) as u32;
    let vl = verilated("pixel_out");
    let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(7));
    let px = pixels(&mut rng, 7, 5, count() * 4, zmax);
    let mut burst = 0;
    let mut ready = |r: &mut ChaCha8Rng| {
        if burst > 0 {
            burst -= 1;
            return false;
        }
        if r.gen_bool(0.05) {
            burst = r.gen_range(1..6);
        }
        r.gen_bool(0.75)
    };
    for rdw in [ReadDuringWrite::Old, ReadDuringWrite::New] {
        run(&mut dual(&vl), true, &px, (7, 5), rdw, &mut ready).unwrap_or_else(|e| panic!("seed {seed}, {rdw:?}: {e}"));
    }
}

/// Latency 2 (`model::pixel_out::LATENCY`): a pixel taken in cycle 0 is read in cycle 0
/// (`mem$rd_en`, its address `{y, x}`) and written in cycle 2.
#[test]
fn pixel_out_latency_is_2() {
    assert_eq!(LATENCY, 2);
    let vl = verilated("pixel_out");
    let mut d = dual(&vl);
    let mut mem = Memory::new(CLASS, 1, (8, 8), 65535, [0; 3], ReadDuringWrite::Old);
    let p = Pixel { x: 3, y: 5, z: 100, rgb: [1, 2, 3] };
    let mut pins =
        vec![("inp$valid", Value::new(1, 1)), ("mem$ready", Value::new(1, 1)), ("mem$rd_z", mem.rd_z_value(DEPTH))];
    let p = pixel("inp", &p);
    pins.extend(as_pins(&p));
    let mut seen = Vec::new();
    for t in 0..4 {
        if t == 1 {
            pins[0].1 = Value::new(1, 0);
        }
        pins[2].1 = mem.rd_z_value(DEPTH);
        let out = d.cycle(&pins).unwrap_or_else(|m| panic!("{m}"));
        let req = Request::of(&out);
        seen.push((req.rd_en, req.wr_en));
        if t == 0 {
            assert_eq!(req.rd_addr, (5 << rtl::widths::SCREEN) | 3, "address {{y, x}}");
        }
        mem.edge(true, &req);
    }
    assert_eq!(seen, [(1, 0), (0, 0), (0, 1), (0, 0)]);
    assert_eq!((mem.depth[5 * 8 + 3], mem.rgb[5 * 8 + 3]), (100, [1, 2, 3]));
}

/// Without the depth test (`DEPTH_TEST = 0`, `rtl::switch`): pixels on distinct addresses,
/// which need none, are all written as the model writes them, in both simulators, with
/// the memory stalling, and no depth is read; a farther pixel on a written address
/// overwrites it, which the model refuses: the logic is gone.
#[test]
fn pixel_out_without_depth_test_vs_model() {
    let seed = seed();
    let zmax = z_max(&rtl::widths::FORMATS) as u32;
    let (w, h) = (64u32, 48u32);
    let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(11));
    let mut seen = std::collections::HashSet::new();
    let px: Vec<Pixel> = pixels(&mut rng, w, h, count() * 2, zmax)
        .into_iter()
        .filter(|p| p.z < zmax && seen.insert((p.x, p.y)))
        .collect();
    let vl = verilated_with("pixel_out", [("DEPTH_TEST", 0)]);
    let dual = || {
        Dual::new(
            PixelOut::new(&Parts { depth_test: false, ..Parts::ALL }),
            vl.model().unwrap_or_else(|e| panic!("{e}")),
        )
    };
    let (mem, _) = run(&mut dual(), false, &px, (w, h), ReadDuringWrite::Old, |r| r.gen_bool(0.8))
        .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    assert_eq!(mem.writes, px.len() as u64, "every pixel written");
    let p = |z| Pixel { x: 1, y: 1, z, rgb: [9, 9, 9] };
    assert!(
        run(&mut dual(), false, &[p(100), p(200)], (w, h), ReadDuringWrite::Old, |_| true).is_err(),
        "the farther pixel overwrites"
    );
}

/// The unit for chunks of four pixels (`LANES = 4`, `rtl::pixel_out::ChunkOut`).
type Chunk4 = ChunkOut<4, { ADDR - 2 }, { 4 * DEPTH }, { 4 * RGB }>;

/// A chunk: its row, its place in the row (x / 4), and per lane a pixel or none.
type Chunk = (u32, u32, [Option<(u32, [u8; 3])>; 4]);

/// Random chunks of four on a `w` x `h` screen (lanes past `w` empty), skewed toward
/// read-after-write hazards: a chunk often on the address of one 1, 2 or 3 before it, its
/// lanes a new random set, a lane's depth often that of the same lane before.
fn chunks(rng: &mut ChaCha8Rng, w: u32, h: u32, n: usize, zmax: u32) -> Vec<Chunk> {
    let mut out: Vec<Chunk> = Vec::with_capacity(n);
    for i in 0..n {
        let back = rng.gen_range(1..=4);
        let (y, c) = if i >= back && rng.gen_bool(0.6) {
            (out[i - back].0, out[i - back].1)
        } else {
            (rng.gen_range(0..h), rng.gen_range(0..w.div_ceil(4)))
        };
        let lanes = std::array::from_fn(|k| {
            let on = 4 * c + (k as u32) < w && rng.gen_bool(0.7);
            let z = match (i >= back).then(|| out[i - back].2[k]).flatten() {
                Some((z, _)) if rng.gen_bool(0.4) => z,
                _ => [0, zmax, zmax - 1, rng.gen_range(0..=zmax)][rng.gen_range(0..4)],
            };
            on.then(|| (z, rng.gen()))
        });
        out.push((y, c, lanes));
    }
    out
}

/// Sends `chunks` (`in_valid` low 20% of the time) with the memory ready when `ready` says;
/// checks each read's lanes, each chunk's writes `LATENCY` ready cycles after it came in
/// against the model's writes of its pixels in lane order, and the buffers at the end.
fn run_chunks(
    dual: &mut Dual<Chunk4>,
    chunks: &[Chunk],
    (w, h): (u32, u32),
    rdw: ReadDuringWrite,
    mut ready: impl FnMut(&mut ChaCha8Rng) -> bool,
) -> Result<Memory, String> {
    let zmax = z_max(&rtl::widths::FORMATS) as u32;
    let mut model = Framebuffer::new(w, h, zmax, [7, 8, 9]);
    let mut mem = Memory::new(CLASS, 4, (w, h), zmax, [7, 8, 9], rdw);
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut due: VecDeque<(u64, Vec<Write>)> = VecDeque::new();
    let (mut next, mut ready_cycle) = (0, 0u64);
    while next < chunks.len() || !due.is_empty() {
        let mem_ready = ready(&mut rng);
        let valid = next < chunks.len() && rng.gen_bool(0.8);
        let (y, c, lanes) = chunks[next.min(chunks.len() - 1)];
        let mask = (0..4).filter(|&k| lanes[k].is_some()).map(|k| 1u8 << k).sum::<u8>();
        let zs = lanes.map(|l| l.map_or(0, |(z, _)| z));
        let rgbs = lanes.map(|l| l.map_or(0, |(_, [r, g, b])| u32::from_be_bytes([0, r, g, b])));
        let pins = [
            ("in_valid", Value::new(1, valid as u128)),
            ("in_mask", Value::new(4, mask as u128)),
            ("in_addr", Value::new(ADDR - 2, ((y << (SCREEN - 2)) | c) as u128)),
            ("in_z", pack(&zs, DEPTH, 4)),
            ("in_rgb", pack(&rgbs, RGB, 4)),
            ("mem$ready", Value::new(1, mem_ready as u128)),
            ("mem$rd_z", mem.rd_z_value(DEPTH)),
        ];
        let out = dual.cycle(&pins).map_err(|m| m.to_string())?;
        let cycle = dual.cycles() - 1;
        if (out.get("in_ready") == &Value::new(1, 1)) != mem_ready {
            return Err(format!("cycle {cycle}: in_ready differs from mem$ready"));
        }
        let req = Request::of(&out);
        if req.rd_en != if valid { mask } else { 0 } {
            return Err(format!("cycle {cycle}: rd_en {:#b} for a chunk of lanes {mask:#b}", req.rd_en));
        }
        let writes = mem.edge(mem_ready, &req);
        if !mem_ready {
            if !writes.as_slice().is_empty() {
                return Err(format!("cycle {cycle}: a write without mem_ready"));
            }
            continue;
        }
        let want = match due.front() {
            Some((at, _)) if *at == ready_cycle => due.pop_front().map(|(_, w)| w).unwrap_or_default(),
            _ => Vec::new(),
        };
        if writes.as_slice() != want.as_slice() {
            return Err(format!("cycle {cycle} (ready cycle {ready_cycle}): wrote {writes:?}, model {want:?}"));
        }
        if valid {
            let mut w = Vec::new();
            for (k, lane) in lanes.iter().enumerate() {
                if let Some((z, rgb)) = *lane {
                    let p = Pixel { x: 4 * c + k as u32, y, z, rgb };
                    if model.pixel_out(&p, 0) {
                        w.push(Write { x: p.x, y, z, rgb });
                    }
                }
            }
            due.push_back((ready_cycle + LATENCY as u64, w));
            next += 1;
        }
        ready_cycle += 1;
    }
    if (mem.depth.clone(), mem.rgb.clone()) != (model.depth, model.rgb) {
        return Err("the buffers differ from the model's".into());
    }
    Ok(mem)
}

/// Chunks of four pixels (`LANES = 4`: the memory port of `raster_top` with a 4-lane vector
/// unit) in rust-hdl and Verilator in lockstep, with many hazards between chunks on one
/// address and lanes written or not, a screen whose width is not a multiple of four, the
/// memory ready or stalling, either read-during-write: every lane's write as the model's.
#[test]
fn pixel_out_chunks_vs_model() {
    let seed = seed();
    let zmax = z_max(&rtl::widths::FORMATS) as u32;
    let vl = verilated_with("pixel_out", [("LANES", 4)]);
    let dual = || Dual::new(Chunk4::new(&Parts::ALL), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(21));
    let ch = chunks(&mut rng, 13, 5, count() * 4, zmax);
    for rdw in [ReadDuringWrite::Old, ReadDuringWrite::New] {
        let mem = run_chunks(&mut dual(), &ch, (13, 5), rdw, |_| true).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        let pixels = ch.iter().flat_map(|c| c.2).flatten().count() as u64;
        assert!(mem.writes > 0 && mem.writes < pixels, "some pixels pass, some fail");
        run_chunks(&mut dual(), &ch, (13, 5), rdw, |r| r.gen_bool(0.7))
            .unwrap_or_else(|e| panic!("seed {seed}, stalling: {e}"));
    }
}
