//! The blending pixel output unit (`pixel_out` with `BLEND` = 1,
//! `rtl::pixel_out::PixelOutBlend`): rust-hdl and Verilator in lockstep, every cycle, with
//! the depth and colour buffers in Rust (`testbenches::memory`, whose reads return the
//! colour too), against `model::pixel_out::Framebuffer::pixel_out_blended` on the same
//! pixels: the same writes (address, depth and blended colour) in the same order, each
//! `LATENCY` cycles of a ready memory after its pixel came in, and the same buffers at the
//! end; pixels on one address back to back and one, two and three apart, in every mode,
//! blended in order as the model blends them one after the other.

use super::pixel_out::{buffers, lockstep};
use model::blend::{MODES, WORKED, WORKED_SRC_DST};
use model::cull_sort::z_max;
use model::pixel_out::LATENCY;
use model::span::Pixel;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::pixel_out::PixelOutBlend;
use rtl::switch::Parts;
use rtl::widths::{CLASS, DEPTH, SCREEN};
use testbenches::memory::{Memory, ReadDuringWrite, Request, Write};
use testbenches::streams::{as_pins, blend_pixel};
use testbenches::{count, seed, verilated_with, Dual, Value, Verilated};
use texture::BlendMode;

/// A pixel to blend: the pixel, its alpha and its mode's code at the unit (`rtl::blend`:
/// `MODES`' index, 6 and 7 opaque).
type Frag = (Pixel, u8, u8);

/// The mode of code `code` (6 and 7: opaque, as `rtl::blend` reads them).
fn mode_of(code: u8) -> BlendMode {
    MODES.get(code as usize).copied().unwrap_or(BlendMode::Opaque)
}

/// Random pixels to blend on a `w` x `h` screen, skewed toward read-after-write hazards
/// that pass the depth test: a pixel often repeats the address of one 1, 2 or 3 pixels
/// before it, then mostly a little nearer than that address's depth (so it passes and
/// blends onto the colour just written), else as near, or random; alphas often 0, 255 or
/// near them, every mode, now and then codes 6 and 7.
fn frags(rng: &mut ChaCha8Rng, (w, h): (u32, u32), n: usize, zmax: u32) -> Vec<Frag> {
    let mut depth = vec![zmax; (w * h) as usize];
    let mut out: Vec<Frag> = Vec::with_capacity(n);
    for i in 0..n {
        let back = rng.gen_range(1..=3);
        let (x, y) = if i >= back && rng.gen_bool(0.6) {
            (out[i - back].0.x, out[i - back].0.y)
        } else {
            (rng.gen_range(0..w), rng.gen_range(0..h))
        };
        let at = (y * w + x) as usize;
        let z = match rng.gen_range(0..10) {
            0..=5 if depth[at] > 0 => depth[at] - rng.gen_range(1..=depth[at].min(3)),
            6 => depth[at],
            7 => [0, zmax, zmax - 1][rng.gen_range(0..3)],
            _ => rng.gen_range(0..=zmax),
        };
        depth[at] = depth[at].min(z);
        let alpha = match rng.gen_range(0..4) {
            0 => [0, 1, 127, 128, 254, 255][rng.gen_range(0..6)],
            _ => rng.gen(),
        };
        let code = if rng.gen_bool(0.05) { rng.gen_range(6..8) } else { rng.gen_range(0..6) };
        out.push((Pixel { x, y, z, rgb: rng.gen() }, alpha, code));
    }
    out
}

/// What a run saw: the memory at the end, and of the pixels written, how many were on the
/// address of a pixel written 1, 2 and 3 pixels before it (the hazards, forwarded or not).
struct Ran {
    mem: Memory,
    after_written: [u64; 3],
}

/// Sends `frags` through `pixel_out`'s lockstep run (the memory cleared to `background`):
/// checks every write against the model's (`pixel_out_blended`) and that the word of every
/// pixel is read as it comes in (depth and colour, with the depth test or without it).
fn run(
    dual: &mut Dual<PixelOutBlend>,
    frags: &[Frag],
    size: (u32, u32),
    background: [u8; 3],
    rdw: ReadDuringWrite,
    ready: impl FnMut(&mut ChaCha8Rng) -> bool,
) -> Result<Ran, String> {
    let mut written: Vec<Option<(u32, u32)>> = Vec::new();
    let mut after_written = [0; 3];
    let mem = lockstep(
        dual,
        frags.len(),
        buffers(size, background, rdw),
        ready,
        |i, mem| {
            let (p, alpha, code) = &frags[i];
            let mut pins = vec![("mem$rd_rgb".to_string(), mem.rd_rgb_value())];
            pins.extend(blend_pixel("inp", p, *alpha, *code));
            pins
        },
        |req, i, valid| {
            let p = &frags[i].0;
            match req.rd_en != valid as u8 || (valid && req.rd_addr != (p.y << SCREEN) | p.x) {
                true => Err(format!("read {} at {:#x} for inp$valid {valid}", req.rd_en, req.rd_addr)),
                false => Ok(()),
            }
        },
        |fb, i| {
            let (p, alpha, code) = &frags[i];
            let w = fb.pixel_out_blended(p, *alpha, mode_of(*code), 0).then(|| {
                let rgb = fb.rgb[(p.y * fb.width + p.x) as usize];
                Write { x: p.x, y: p.y, z: p.z, rgb }
            });
            if w.is_some() {
                for (d, n) in after_written.iter_mut().enumerate() {
                    *n += u64::from(written.len() > d && written[written.len() - 1 - d] == Some((p.x, p.y)));
                }
            }
            written.push(w.map(|w| (w.x, w.y)));
            w
        },
    )?;
    Ok(Ran { mem, after_written })
}

fn verilated(depth_test: bool) -> std::sync::Arc<Verilated> {
    verilated_with("pixel_out", [("BLEND", 1), ("DEPTH_TEST", depth_test as u64)])
}

fn dual(vl: &Verilated, depth_test: bool) -> Dual<PixelOutBlend> {
    Dual::new(PixelOutBlend::new(&Parts { depth_test, ..Parts::ALL }), vl.model().unwrap_or_else(|e| panic!("{e}")))
}

/// Random pixels with many hazards that pass and fail the depth test, random alphas, every
/// mode, the memory always ready and stalling, either read-during-write behaviour: every
/// write, its blended colour included, as the model's, LATENCY cycles after its pixel; the
/// buffers equal to the model's; passing pixels right behind passing pixels on their
/// address, at distances 1, 2 and 3, did occur.
#[test]
fn pixel_out_blend_random_vs_model() {
    let seed = seed();
    let zmax = z_max(&rtl::widths::FORMATS) as u32;
    let vl = verilated(true);
    let stall = |r: &mut ChaCha8Rng| r.gen_bool(0.7);
    for (i, (size, rdw, stalls)) in [
        ((7, 5), ReadDuringWrite::Old, false),
        ((7, 5), ReadDuringWrite::New, false),
        ((7, 5), ReadDuringWrite::Old, true),
        ((7, 5), ReadDuringWrite::New, true),
        ((3, 2), ReadDuringWrite::Old, true),
        ((64, 48), ReadDuringWrite::Old, false),
    ]
    .into_iter()
    .enumerate()
    {
        let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(100 + i as u64));
        let px = frags(&mut rng, size, count() * 4, zmax);
        let ready = |r: &mut ChaCha8Rng| !stalls || stall(r);
        let ran = run(&mut dual(&vl, true), &px, size, [60, 120, 200], rdw, ready)
            .unwrap_or_else(|e| panic!("seed {seed}, case {i} ({size:?}, {rdw:?}, stalls {stalls}): {e}"));
        assert!(ran.mem.writes > 0 && ran.mem.writes < px.len() as u64, "some pixels pass, some fail");
        // Passing pixels on one address grow with the log of its visits (each must beat the
        // depth written so far), so the count of hazards asked for stops growing at 100.
        if size == (7, 5) {
            assert!(
                ran.after_written.iter().all(|&n| n > (count() as u64 / 10).min(100)),
                "hazards that pass: {:?} at distances 1, 2, 3",
                ran.after_written
            );
        }
    }
}

/// The worked example (`model::blend::WORKED`): (200, 30, 160) at alpha 128 onto (60, 120,
/// 200) in each of the six modes, one pixel a mode on its own address of a memory cleared
/// to that colour: the read at its first cycle, the write at its third, the colour written
/// the worked one; then the six again on one address back to back, each onto the last.
#[test]
fn pixel_out_blend_worked_example() {
    assert_eq!(LATENCY, 2);
    let vl = verilated(true);
    let (src, dst) = WORKED_SRC_DST;
    let background = [dst[0], dst[1], dst[2]];
    let code = |mode| MODES.iter().position(|m| *m == mode).unwrap() as u8;
    let pixel = |x, z| Pixel { x, y: 5, z, rgb: [src[0], src[1], src[2]] };
    // Each mode alone, the pipeline empty around it.
    for (i, (mode, want)) in WORKED.into_iter().enumerate() {
        let mut d = dual(&vl, true);
        let mut mem = Memory::new(CLASS, 1, (8, 8), 65535, background, ReadDuringWrite::Old);
        let mut seen = Vec::new();
        for t in 0..4 {
            let mut pins = vec![
                ("inp$valid", Value::new(1, (t == 0) as u128)),
                ("mem$ready", Value::new(1, 1)),
                ("mem$rd_z", mem.rd_z_value(DEPTH)),
                ("mem$rd_rgb", mem.rd_rgb_value()),
            ];
            let fields = blend_pixel("inp", &pixel(i as u32, 100), src[3], code(mode));
            pins.extend(as_pins(&fields));
            let out = d.cycle(&pins).unwrap_or_else(|m| panic!("{m}"));
            let req = Request::of(&out);
            seen.push((req.rd_en, req.wr_en));
            let w = mem.edge(true, &req);
            if t == 2 {
                let rgb = [want[0], want[1], want[2]];
                assert_eq!(w.as_slice(), [Write { x: i as u32, y: 5, z: 100, rgb }], "{mode:?}");
            }
        }
        assert_eq!(seen, [(1, 0), (0, 0), (0, 1), (0, 0)], "{mode:?}: read at 0, written at 2");
    }
    // The six on one address back to back, each nearer: each blends onto the one before
    // (forwarded from s2), as the model blends them in turn.
    let px: Vec<Frag> =
        WORKED.iter().enumerate().map(|(i, (mode, _))| (pixel(2, 100 - i as u32), src[3], code(*mode))).collect();
    let ran = run(&mut dual(&vl, true), &px, (8, 8), background, ReadDuringWrite::Old, |_| true)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(ran.mem.writes, 6);
}

/// Without the depth test (`DEPTH_TEST` = 0): every pixel is read (its colour) and written,
/// blended, on distinct addresses as the model writes them, the memory stalling.
#[test]
fn pixel_out_blend_without_depth_test_vs_model() {
    let seed = seed();
    let zmax = z_max(&rtl::widths::FORMATS) as u32;
    let size = (64u32, 48u32);
    let mut rng = ChaCha8Rng::seed_from_u64(seed.wrapping_add(131));
    let mut seen = std::collections::HashSet::new();
    let px: Vec<Frag> = frags(&mut rng, size, count() * 2, zmax)
        .into_iter()
        .filter(|(p, _, _)| p.z < zmax && seen.insert((p.x, p.y)))
        .collect();
    let vl = verilated(false);
    let ran = run(&mut dual(&vl, false), &px, size, [60, 120, 200], ReadDuringWrite::Old, |r| r.gen_bool(0.8))
        .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    assert_eq!(ran.mem.writes, px.len() as u64, "every pixel written");
}
