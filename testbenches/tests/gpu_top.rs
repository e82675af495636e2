//! `gpu_top`: whole frames through the core as a host drives it, in Verilator: the
//! registers written over AXI4-Lite, START, the vertex buffer read from one memory
//! (`model::read_memory`), the depth and colour buffers in two others
//! (`model::word_memory`), until the interrupt; then `STATUS`, `FRAME_CYCLES` and
//! `TRIANGLES` read back. The buffers must equal the model's frame (`model::raster_top`) of
//! the same buffer, and nothing may be read or written outside them.

use model::cull_sort::Cull;
use model::gpu_regs::Reg;
use model::raster_top::raster_top;
use model::read_memory::{ReadMemory, ReadRequest};
use model::vertex_buffer::{broken, Fault, VertexBuffer};
use model::word_memory::{WordMemory, WordRequest};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::gpu_top::GpuTop;
use rtl::switch::Parts;
use testbenches::stimulus::shipped_buffers;
use testbenches::streams::as_pins;
use testbenches::{count, verilated_with, Dual, Outputs, PortDir, Sim, Value, VlSim};

const VB_BASE: u32 = 0x1000;
const DEPTH_BASE: u32 = 0x10_0000;
const COLOR_BASE: u32 = 0x40_0000;
const FILL: u32 = 0xdead_beef;

/// One cycle of the core in a simulator: drives the inputs named, settles, returns every
/// output, clocks.
type Step = Box<dyn FnMut(&[(&str, Value)]) -> Outputs>;

/// The core in Verilator.
fn verilator() -> Step {
    let mut vl: VlSim = verilated_with("gpu_top", []).model().unwrap_or_else(|e| panic!("{e}"));
    let outputs: Vec<String> = vl.ports().iter().filter(|p| p.dir == PortDir::Out).map(|p| p.name.clone()).collect();
    Box::new(move |pins| {
        for (n, v) in pins {
            vl.set(n, v);
        }
        vl.settle();
        let o = Outputs(outputs.iter().map(|n| (n.clone(), vl.get(n))).collect());
        vl.clock();
        o
    })
}

/// The core in rust-hdl and Verilator in lockstep, every output compared every cycle.
fn dual() -> Step {
    let vl = verilated_with("gpu_top", []).model().unwrap_or_else(|e| panic!("{e}"));
    let parts = Parts::of(&Default::default()).expect("every part");
    let unit = GpuTop::new(7, model::divider::LATENCY as usize, &parts).expect("the default core");
    let mut dual = Dual::new(unit, vl);
    Box::new(move |pins| dual.cycle(pins).unwrap_or_else(|m| panic!("{m}")))
}

/// The core with its memories, driven as a host drives it.
struct Soc<'a> {
    step: Step,
    vb: ReadMemory<'a>,
    depth: WordMemory<'a>,
    color: WordMemory<'a>,
    cycle: u64,
}

/// A register access of the host: a write (data) or a read.
enum Access {
    Write(Reg, u32),
    Read(Reg),
}

impl<'a> Soc<'a> {
    /// The memories answer `latency` cycles late, and each channel holds back a transfer
    /// in a cycle with chance `stall`.
    fn new(step: Step, vb: &'a [u8], (width, height): (u32, u32), latency: u32, stall: f64) -> Soc<'a> {
        let words = (width * height) as usize;
        let stalls = |seed: u64| {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            move || rng.gen_bool(stall)
        };
        Soc {
            step,
            vb: ReadMemory::new(vb, VB_BASE, 8, latency, stalls(1)),
            depth: WordMemory::new(vec![FILL; words], DEPTH_BASE, latency, stalls(2)),
            color: WordMemory::new(vec![FILL; words], COLOR_BASE, latency, stalls(3)),
            cycle: 0,
        }
    }

    /// One cycle with the host's pins `host`: the memories answer, the outputs are read,
    /// the clock ticks.
    fn cycle(&mut self, host: &[(&str, Value)]) -> Outputs {
        let bit = |b: bool| Value::new(1, b as u128);
        let (r, z, c) = (self.vb.response(), self.depth.response(), self.color.response());
        let mut pins: Vec<(String, Value)> = host.iter().map(|(n, v)| (n.to_string(), v.clone())).collect();
        pins.extend([
            ("vb$ar_ready".into(), bit(r.ar_ready)),
            ("vb$r_valid".into(), bit(r.r_valid)),
            ("vb$r_data".into(), Value::new(64, u128::from(r.r_data[0]) | u128::from(r.r_data[1]) << 32)),
            ("vb$r_resp".into(), Value::new(2, if r.r_error { 2 } else { 0 })),
            ("zr$ar_ready".into(), bit(z.ar_ready)),
            ("zr$r_valid".into(), bit(z.r_valid)),
            ("zr$r_data".into(), Value::new(32, z.r_data.into())),
            ("zr$r_resp".into(), Value::new(2, if z.r_error { 2 } else { 0 })),
        ]);
        for (bus, m) in [("zw", &z), ("cw", &c)] {
            pins.extend([
                (format!("{bus}$aw_ready"), bit(m.aw_ready)),
                (format!("{bus}$w_ready"), bit(m.w_ready)),
                (format!("{bus}$b_valid"), bit(m.b_valid)),
                (format!("{bus}$b_resp"), Value::new(2, if m.b_error { 2 } else { 0 })),
            ]);
        }
        let o = (self.step)(&as_pins(&pins));
        let on = |pin: &str| o.get(pin).bit(0);
        let word = |pin: &str| o.get(pin).to_u128() as u32;
        let ar = on("vb$ar_valid").then(|| ReadRequest { addr: word("vb$ar_addr"), beats: word("vb$ar_len") + 1 });
        self.vb.clock(ar, on("vb$r_ready"));
        let request = |bus: &str, reads: bool| WordRequest {
            ar: (reads && on("zr$ar_valid")).then(|| word("zr$ar_addr")),
            aw: on(&format!("{bus}$aw_valid")).then(|| word(&format!("{bus}$aw_addr"))),
            w: on(&format!("{bus}$w_valid")).then(|| word(&format!("{bus}$w_data"))),
            r_ready: true,
            b_ready: true,
        };
        self.depth.clock(&request("zw", true));
        self.color.clock(&request("cw", false));
        self.cycle += 1;
        o
    }

    /// One register access, from offer to answer; returns the read's data (0 for a write)
    /// and asserts an OKAY answer.
    fn access(&mut self, a: Access) -> u32 {
        let bit = |b: bool| Value::new(1, b as u128);
        let (addr, data, write) = match a {
            Access::Write(r, d) => (r as u32, d, true),
            Access::Read(r) => (r as u32, 0, false),
        };
        let offer = vec![
            ("host$aw_valid", bit(write)),
            ("host$w_valid", bit(write)),
            ("host$aw_addr", Value::new(6, addr.into())),
            ("host$w_data", Value::new(32, data.into())),
            ("host$w_strb", Value::new(4, 15)),
            ("host$ar_valid", bit(!write)),
            ("host$ar_addr", Value::new(6, addr.into())),
            ("host$b_ready", bit(true)),
            ("host$r_ready", bit(true)),
        ];
        let taken = if write { "host$w_ready" } else { "host$ar_ready" };
        while !self.cycle(&offer).get(taken).bit(0) {}
        let idle = [("host$aw_valid", bit(false)), ("host$w_valid", bit(false)), ("host$ar_valid", bit(false))];
        loop {
            let o = self.cycle(&idle);
            let (valid, resp) = if write { ("host$b_valid", "host$b_resp") } else { ("host$r_valid", "host$r_resp") };
            if o.get(valid).bit(0) {
                assert_eq!(o.get(resp).to_u128(), 0, "{:?} answered an error", addr);
                return if write { 0 } else { o.get("host$r_data").to_u128() as u32 };
            }
        }
    }

    /// A frame of the buffer at `VB_BASE`: the registers, START, cycles until the
    /// interrupt (at most `limit`); returns `STATUS`, `FRAME_CYCLES`, `TRIANGLES`.
    fn frame(&mut self, width: u32, clear: bool, limit: u64) -> (u32, u32, u32) {
        for (r, v) in [
            (Reg::VbAddr, VB_BASE),
            (Reg::ColorBase, COLOR_BASE),
            (Reg::ColorPitch, 4 * width),
            (Reg::DepthBase, DEPTH_BASE),
            (Reg::DepthPitch, 4 * width),
            (Reg::Control, (clear as u32) << 1 | 4 | 1),
        ] {
            self.access(Access::Write(r, v));
        }
        let start = self.cycle;
        let none: [(&str, Value); 0] = [];
        while !self.cycle(&none).get("irq").bit(0) {
            if self.cycle - start >= limit {
                let status = self.access(Access::Read(Reg::Status));
                let t = self.access(Access::Read(Reg::Triangles));
                panic!("no interrupt in {limit} cycles: STATUS {status:#x}, {t} triangles, {} depth writes, {} colour writes", self.depth.written.len(), self.color.written.len());
            }
        }
        self.access(Access::Write(Reg::Irq, 1));
        let status = self.access(Access::Read(Reg::Status));
        (status, self.access(Access::Read(Reg::FrameCycles)), self.access(Access::Read(Reg::Triangles)))
    }
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
/// `raster_top`'s fed directly (`model::raster_top`'s count); the cube, whose pixels set
/// the pace, must take at most 5% more.
#[test]
fn gpu_top_shipped_scenes_vs_model() {
    for (scene, vb) in shipped_buffers() {
        let slow = scene.ends_with("cube.json") || count() >= 10_000;
        let paces: &[(u32, f64)] = if slow { &[(0, 0.0), (20, 0.3)] } else { &[(0, 0.0)] };
        let bytes = vb.encode();
        let (color, depth) = model_frame(&vb);
        for &(latency, stall) in paces {
            let mut soc = Soc::new(verilator(), &bytes, (vb.width, vb.height), latency, stall);
            let (status, cycles, triangles) = soc.frame(vb.width, true, 20_000_000);
            assert_eq!(status & 0xfff, 0, "{scene}: STATUS {status:#x}");
            assert_eq!(triangles as usize, vb.triangles.len(), "{scene}");
            assert_eq!(soc.color.words, color, "{scene}, latency {latency}: colour");
            assert_eq!(soc.depth.words, depth, "{scene}, latency {latency}: depth");
            let (status, again, _) = soc.frame(vb.width, false, 20_000_000);
            assert_eq!(status & 0xfff, 0);
            assert_eq!((&soc.color.words, &soc.depth.words), (&color, &depth), "{scene}: drawn again");
            let outside = (soc.depth.outside_reads, soc.depth.outside_writes, soc.color.outside_writes);
            assert_eq!(outside, (0, 0, 0));
            let cull = if vb.cull_back { Cull::Back } else { Cull::None };
            let direct = raster_top(&vb.build, &vb.to_trilist(), cull, vb.background).expect("draws").cycles();
            eprintln!(
                "gpu_top: {scene}, latency {latency}: {cycles} cycles cleared, {again} again; raster_top fed directly {direct}"
            );
            if scene.ends_with("cube.json") && latency == 0 {
                assert!(u64::from(again) * 100 <= direct * 105, "{again} cycles against {direct}");
            }
        }
    }
}

/// A broken buffer ends the frame with the parser's fault in `STATUS`, and writes nothing
/// but the clear.
#[test]
fn gpu_top_broken_buffer_sets_the_fault() {
    let fan = broken::fan();
    let (_, bytes, fault) = broken::cases().into_iter().find(|c| c.2 != Fault::Bus).expect("a case");
    let mut soc = Soc::new(verilator(), &bytes, (fan.width, fan.height), 0, 0.0);
    let (status, _, _) = soc.frame(fan.width, false, 100_000);
    assert_eq!(status & 0x1ff, model::gpu_top::status(Some(fault)), "STATUS {status:#x}");
    assert!(soc.depth.written.is_empty() && soc.color.written.is_empty());
}

/// Two overlapping triangles on 16 x 16 (`model::gpu_top::overlap`) through rust-hdl and
/// Verilator in lockstep, cleared, at latency 3 with the memories stalling 20% of the
/// cycles: both simulators give the same outputs every cycle, and the buffers are the
/// model's.
#[test]
fn gpu_top_small_frame_both_simulators() {
    let vb = model::gpu_top::overlap();
    let bytes = vb.encode();
    let mut soc = Soc::new(dual(), &bytes, (vb.width, vb.height), 3, 0.2);
    let (status, _, triangles) = soc.frame(vb.width, true, 100_000);
    assert_eq!((status & 0xfff, triangles as usize), (0, vb.triangles.len()));
    let (color, depth) = model_frame(&vb);
    assert_eq!((soc.color.words.clone(), soc.depth.words.clone()), (color, depth));
}
