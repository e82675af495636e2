//! `gpu_top`: whole frames through the core as a host drives it (`sim::soc`), in
//! Verilator: the registers written over AXI4-Lite, START, the vertex buffer read from one
//! memory, the depth and colour buffers in two others, until the interrupt; then `STATUS`,
//! `FRAME_CYCLES` and `TRIANGLES` read back. The buffers must equal the model's frame
//! (`model::gpu_top`) of the same buffer, also for broken, hostile and random buffers, and
//! nothing may be read or written outside them.

use model::cull_sort::Cull;
use model::gpu_regs::Reg;
use model::gpu_top::{run, Ending};
use model::raster_top::raster_top;
use model::vertex_buffer::{broken, pack, Fault, VertexBuffer};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::gpu_top::GpuTop;
use rtl::switch::Parts;
use scene::{Trilist, Vertex};
use sim::soc::{self, ByName, Core, Pace, Soc, FILL, VB_BASE};
use testbenches::stimulus::shipped_buffers;
use testbenches::{count, seed, Dual};

/// The core in Verilator.
fn verilator() -> Box<dyn Core> {
    soc::verilator().unwrap_or_else(|e| panic!("{e}"))
}

/// The core in rust-hdl and Verilator in lockstep, every output compared every cycle.
fn dual() -> Box<dyn Core> {
    let vl = testbenches::verilated_with("gpu_top", []).model().unwrap_or_else(|e| panic!("{e}"));
    let parts = Parts::of(&Default::default()).expect("every part");
    let unit = GpuTop::new(7, model::divider::LATENCY as usize, &parts).expect("the default core");
    let mut dual = Dual::new(unit, vl);
    Box::new(ByName(Box::new(move |pins| dual.cycle(pins).map_err(|m| m.to_string()))))
}

/// Memories answering `latency` cycles late, each channel holding back a transfer in a
/// cycle with chance `stall`.
fn pace(latency: u32, stall: f64, seed: u64) -> Pace<'static> {
    let stalls = [1, 2, 3].map(|k| {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ k);
        Box::new(move || rng.gen_bool(stall)) as Box<dyn FnMut() -> bool>
    });
    Pace { latency, stalls }
}

/// `vb`'s frame as the model draws it: the colour and depth words of each pixel.
fn model_frame(vb: &VertexBuffer) -> (Vec<u32>, Vec<u32>) {
    let f = model::gpu_top::frame(vb).unwrap_or_else(|e| panic!("{e}"));
    (f.color, f.depth)
}

/// Every shipped scene at class 10 packed into a vertex buffer and drawn through
/// `gpu_top`, the buffers cleared, at memory latency 0; the cube also at 20 with every
/// channel stalling 30% of the cycles (every scene in the soak, with `EDGEPAINT_N` of
/// 10,000). The buffers equal the model's frame; `STATUS` says done without
/// error and `TRIANGLES` counts the buffer's triangles. Then each is drawn again without the
/// clear: nothing changes. At latency 0 that frame's cycles are printed beside
/// `raster_top`'s fed directly (`model::raster_top`'s count): at most 5% more on every scene
/// (the knot's 2,400 small triangles, half of them culled, come closest: `triangle_queue`).
#[test]
fn gpu_top_shipped_scenes_vs_model() {
    for (scene, vb) in shipped_buffers() {
        let slow = scene.ends_with("cube.json") || count() >= 10_000;
        let paces: &[(u32, f64)] = if slow { &[(0, 0.0), (20, 0.3)] } else { &[(0, 0.0)] };
        let bytes = vb.encode();
        let (color, depth) = model_frame(&vb);
        for &(latency, stall) in paces {
            let mut soc = Soc::new(verilator(), &bytes, (vb.width, vb.height), pace(latency, stall, 1));
            let end = soc.frame(true, 20_000_000).unwrap_or_else(|e| panic!("{scene}: {e}"));
            assert_eq!(end.status & 0xfff, 0, "{scene}: STATUS {:#x}", end.status);
            assert_eq!(end.triangles as usize, vb.triangles.len(), "{scene}");
            assert_eq!(soc.color.words, color, "{scene}, latency {latency}: colour");
            assert_eq!(soc.depth.words, depth, "{scene}, latency {latency}: depth");
            let again = soc.frame(false, 20_000_000).unwrap_or_else(|e| panic!("{scene}: {e}"));
            assert_eq!(again.status & 0xfff, 0);
            assert_eq!((&soc.color.words, &soc.depth.words), (&color, &depth), "{scene}: drawn again");
            let outside = (soc.depth.outside_reads, soc.depth.outside_writes, soc.color.outside_writes);
            assert_eq!(outside, (0, 0, 0));
            let cull = if vb.cull_back { Cull::Back } else { Cull::None };
            let direct = raster_top(&vb.build, &vb.to_trilist(), cull, vb.background).expect("draws").cycles();
            eprintln!(
                "gpu_top: {scene}, latency {latency}: {} cycles cleared, {} again; raster_top fed directly {direct}",
                end.cycles, again.cycles
            );
            if latency == 0 {
                let more = u64::from(again.cycles) * 100;
                assert!(more <= direct * 105, "{scene}: {} cycles against {direct}", again.cycles);
            }
        }
    }
}

/// Buffers `screen` pixels large holding what `ending` says: the model's frame in its
/// header's screen (rows `4 * screen.0` bytes apart), [`FILL`] elsewhere.
fn expected_words(ending: &Ending, screen: (u32, u32)) -> (Vec<u32>, Vec<u32>) {
    let mut color = vec![FILL; (screen.0 * screen.1) as usize];
    let mut depth = color.clone();
    if let Some((w, h, f)) = &ending.drawn {
        for y in 0..*h as usize {
            for x in 0..*w as usize {
                color[y * screen.0 as usize + x] = f.color[y * *w as usize + x];
                depth[y * screen.0 as usize + x] = f.depth[y * *w as usize + x];
            }
        }
    }
    (color, depth)
}

/// One hostile or ordinary buffer through `gpu_top` on `core`, the buffers `screen`
/// pixels large, cleared: the frame must end (the interrupt within `limit` cycles) with
/// the model's `STATUS` and `TRIANGLES` (`model::gpu_top::run`), leave the model's words in
/// both buffers and read and write nothing outside them. Returns the simulator, and the
/// model's ending.
fn hostile(
    core: Box<dyn Core>,
    bytes: &[u8],
    screen: (u32, u32),
    p: Pace,
    limit: u64,
    what: &str,
) -> (Box<dyn Core>, Ending) {
    let ending = run(bytes, VB_BASE, [screen.0, screen.1], 10_000_000).unwrap_or_else(|e| panic!("{what}: {e}"));
    let mut soc = Soc::new(core, bytes, screen, p);
    let end = soc.frame(true, limit).unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!((end.status & 0x1ff, end.triangles), (ending.status, ending.triangles), "{what}");
    let (color, depth) = expected_words(&ending, screen);
    assert!(soc.color.words == color, "{what}: colour buffer");
    assert!(soc.depth.words == depth, "{what}: depth buffer");
    let outside = (soc.vb.outside, soc.depth.outside_reads, soc.depth.outside_writes, soc.color.outside_writes);
    assert_eq!(outside, (0, 0, 0, 0), "{what}: transfers outside the memories");
    (soc.into_core(), ending)
}

/// Every broken rule of `vertex_buffer::broken` (among them a triangle list with no end
/// flag), and the fan on buffers one pixel too narrow or too short for its header's
/// screen, then with a colour pitch that holds 15 pixels: each frame ends with the model's fault in `STATUS`, writes
/// the clear and the triangles before the broken record and nothing else, in a bounded
/// number of cycles (2,000; the good fan takes about 600 with the clear).
#[test]
fn gpu_top_broken_buffers_end_with_the_fault() {
    let fan = broken::fan();
    let mut core = verilator();
    let mut faults = Vec::new();
    for (what, bytes, fault) in broken::cases() {
        let e;
        (core, e) = hostile(core, &bytes, (16, 16), Pace::at_once(), 2_000, what);
        assert_eq!(e.status, model::gpu_top::status(Some(fault)), "{what}");
        faults.push(fault);
    }
    let good = fan.encode();
    for screen in [(15, 16), (16, 15)] {
        let e;
        (core, e) = hostile(core, &good, screen, Pace::at_once(), 2_000, "the fan on smaller buffers");
        assert_eq!((e.status, e.drawn), (model::gpu_top::status(Some(Fault::Screen)), None));
    }
    // Buffers of 16 x 16 whose colour rows are 60 bytes apart hold 15 pixels a row.
    let mut soc = Soc::new(core, &good, (16, 16), Pace::at_once());
    let mut writes = soc.registers(true);
    writes.iter_mut().filter(|(r, _)| *r == Reg::ColorPitch).for_each(|w| w.1 = 60);
    let end = soc.frame_with(&writes, 2_000).unwrap_or_else(|e| panic!("{e}"));
    let limit = model::gpu_top::screen_limit(16 << 16 | 16, 60, 64);
    assert_eq!(limit, [15, 16]);
    let e = run(&good, VB_BASE, limit, 10_000).expect("ends");
    assert_eq!((end.status & 0x1ff, e.status), (model::gpu_top::status(Some(Fault::Screen)), e.status));
    assert!(soc.color.written.is_empty() && soc.depth.written.is_empty());
    assert!(faults.contains(&Fault::TriangleInfo) && faults.len() >= 10);
}

/// A random small scene: up to 12 triangles on a screen of 4 to 48 pixels a side, some
/// crossing its edges and z's [0, 1], random colours, cull and background, packed for the
/// default build.
fn random_buffer(rng: &mut ChaCha8Rng) -> Option<VertexBuffer> {
    let (width, height) = (rng.gen_range(4..=48), rng.gen_range(4..=48));
    let vertex = |rng: &mut ChaCha8Rng| {
        let x = rng.gen_range(-8.0..width as f64 + 8.0);
        let y = rng.gen_range(-8.0..height as f64 + 8.0);
        let c = [0; 3].map(|_| rng.gen_range(0.0..255.0));
        Vertex::new(x, y, rng.gen_range(-0.1..1.1), c)
    };
    let triangles = (0..rng.gen_range(1..=12)).map(|_| [0; 3].map(|_| vertex(rng))).collect();
    let list = Trilist { width, height, triangles, textures: Vec::new() };
    let background = [0; 3].map(|_| rng.gen());
    pack(&list, &fx::Build::default(), rng.gen(), background).ok().map(|(vb, _)| vb)
}

/// Random small scenes (`EDGEPAINT_N` / 20 of them), each packed and then, half of
/// the time, edited at random (`broken::mutate`), on buffers of the scene's screen (a
/// tenth of the time one pixel narrower), at random latencies with the memories
/// stalling: through `gpu_top` in Verilator, frame after frame on one core, every frame
/// ends with the model's `STATUS`, `TRIANGLES` and buffers, nothing outside them touched.
#[test]
fn gpu_top_random_and_mutated_buffers_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut core = verilator();
    let (mut faults, mut drawn) = (std::collections::BTreeSet::new(), 0);
    for case in 0..count() / 20 {
        let Some(vb) = random_buffer(&mut rng) else { continue };
        let mut bytes = vb.encode();
        if rng.gen_bool(0.5) {
            broken::mutate(&mut bytes, &mut |n| rng.gen_range(0..n));
        }
        let narrower = rng.gen_bool(0.1) as u32;
        let screen = (vb.width - narrower, vb.height);
        let p = pace(rng.gen_range(0..4), 0.2, rng.gen());
        let what = format!("seed {seed}, case {case}");
        let e;
        (core, e) = hostile(core, &bytes, screen, p, 1_000_000, &what);
        faults.insert(e.status >> model::gpu_top::FAULT_SHIFT);
        drawn += e.triangles;
    }
    eprintln!("gpu_top: {} random buffers, fault codes {faults:?}, {drawn} triangles drawn", count() / 20);
    assert!(faults.len() >= 4 && drawn > 0, "the cases reach drawing and several faults: {faults:?}, {drawn} drawn");
}

/// Two overlapping triangles on 16 x 16 (`model::gpu_top::overlap`) through rust-hdl and
/// Verilator in lockstep, cleared, at latency 3 with the memories stalling 20% of the
/// cycles: both simulators give the same outputs every cycle, and the buffers are the
/// model's.
#[test]
fn gpu_top_small_frame_both_simulators() {
    let vb = model::gpu_top::overlap();
    let bytes = vb.encode();
    let mut soc = Soc::new(dual(), &bytes, (vb.width, vb.height), pace(3, 0.2, 7));
    let end = soc.frame(true, 100_000).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((end.status & 0xfff, end.triangles as usize), (0, vb.triangles.len()));
    let (color, depth) = model_frame(&vb);
    assert_eq!((soc.color.words.clone(), soc.depth.words.clone()), (color, depth));
}
