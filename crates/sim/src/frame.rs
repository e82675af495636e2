//! Whole frames through `raster_top`: triangles in (the model's `Vtx` words, as
//! `model::input::to_fixed` makes them), the depth and colour buffers in Rust
//! ([`Memory`]), the image and the cycle counts out. The frame simulation of `edgepaint
//! render --engine rtl` and of the `raster_top` tests.
//!
//! Cycle 0 is the first cycle the first triangle is offered; a triangle is offered as soon
//! as the one before it is taken (back to back, as `model::cycles` assumes). The frame
//! takes [`FrameOut::cycles`] cycles: `done` is first high in that cycle.

use crate::memory::{pack, pack_words, unpack, Memory, ReadDuringWrite, Request, MAX_LANES, REQUEST};
use crate::streams::{raw, unsigned};
use crate::{HdlSim, Outputs, Pins, PortId, Sim, Value, VlSim};
use fx::Build;
use model::cull_sort::{z_max, Cull};
use model::input::Vtx;
use model::span::Pixel;
use rtl::raster_top::RasterTop;
use rtl::widths::CHANNEL;
use rust_hdl::prelude::Block;
use std::path::Path;

/// `raster_top`'s inputs in one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Drive {
    /// The build of the `raster_top` driven (`rtl::BUILDS`): its port widths.
    pub build: Build,
    pub width: u32,
    pub height: u32,
    pub cull_back: bool,
    pub inp_valid: bool,
    pub inp_last: bool,
    /// The triangle offered (`inp$v<k>_*`).
    pub tri: [Vtx; 3],
    pub mem_ready: bool,
    /// Pixels a memory word (`raster_top`'s `LANES`; 1 but for the vector method's), and
    /// each lane's depth read (`mem$rd_z`).
    pub lanes: u32,
    pub rd_z: [u32; MAX_LANES],
}

/// `raster_top`'s outputs in one cycle, sampled before the clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sense {
    pub inp_ready: bool,
    pub verdict_valid: bool,
    pub verdict_code: u8,
    pub req: Request,
    pub done: bool,
}

/// One clock of `raster_top`, in any simulator: drive the inputs, settle, sample the
/// outputs, clock.
pub trait Cycle {
    fn cycle(&mut self, d: &Drive) -> Result<Sense, String>;
}

/// `v` in the low `width` bits (two's complement).
fn low(width: usize, v: i128) -> u64 {
    (v as u64) & (u64::MAX >> (64 - width))
}

/// Widths of `raster_top`'s inputs in build `build`.
struct InputWidths {
    dim: usize,
    depth: usize,
    xy: usize,
    z: usize,
    color: usize,
    inv_w: usize,
}

impl InputWidths {
    fn of(build: &Build) -> Self {
        let f = build.formats;
        let bits = |f: fx::Fmt| f.bits() as usize;
        InputWidths {
            dim: build.class as usize + 1,
            depth: f.z.frac as usize,
            xy: bits(f.xy),
            z: bits(f.z),
            color: bits(f.color),
            inv_w: bits(f.inv_w),
        }
    }
}

/// The named port values of `d`, for the simulators driven by name.
pub fn named(d: &Drive) -> Vec<(String, Value)> {
    let w = InputWidths::of(&d.build);
    let mut out = vec![
        ("width".to_owned(), Value::new(w.dim, d.width as u128)),
        ("height".into(), Value::new(w.dim, d.height as u128)),
        ("cull_back".into(), Value::new(1, d.cull_back as u128)),
        ("inp$valid".into(), Value::new(1, d.inp_valid as u128)),
        ("inp_last".into(), Value::new(1, d.inp_last as u128)),
        ("mem$ready".into(), Value::new(1, d.mem_ready as u128)),
        ("mem$rd_z".into(), pack(&d.rd_z, w.depth, d.lanes as usize)),
    ];
    out.extend(triangle_pins(&d.build, &d.tri));
    out
}

/// The named input port values (`inp$v<k>_*`) of triangle `tri` in build `build`: the
/// link `inp` of `raster_top` (`links::TriangleSink`, or with `inp$crosses` beside them
/// `links::SortedSink`), at the build's widths.
pub fn triangle_pins(build: &Build, tri: &[Vtx; 3]) -> Vec<(String, Value)> {
    let w = InputWidths::of(build);
    let mut out = Vec::new();
    for (k, v) in tri.iter().enumerate() {
        let p = |f: &str| format!("inp$v{k}_{f}");
        out.push((p("x"), raw(w.xy, v.x)));
        out.push((p("y"), raw(w.xy, v.y)));
        out.push((p("z"), raw(w.z, v.z)));
        for (i, c) in v.c.iter().enumerate() {
            out.push((p(&format!("c{i}")), raw(w.color, *c)));
        }
        out.push((p("iw"), raw(w.inv_w, v.iw)));
    }
    out
}

/// `raster_top`'s outputs that a frame reads, as one cycle's [`Sense`].
pub fn sense(o: &Outputs) -> Sense {
    let high = |pin: &str| unsigned(o.get(pin)) == 1;
    Sense {
        inp_ready: high("inp$ready"),
        verdict_valid: high("verdict$valid"),
        verdict_code: unsigned(o.get("verdict$code")) as u8,
        req: Request::of(o),
        done: high("done"),
    }
}

/// One cycle of a simulator driven by port name.
fn cycle_by_name(sim: &mut impl Sim, d: &Drive) -> Sense {
    for (pin, v) in named(d) {
        sim.set(&pin, &v);
    }
    sim.settle();
    let read =
        ["inp$ready", "verdict$valid", "verdict$code", "done", "mem$rd_en", "mem$rd_addr", "mem$wr_en", "mem$wr_addr"];
    let o = Outputs(read.iter().chain(&["mem$wr_z", "mem$wr_rgb"]).map(|p| (p.to_string(), sim.get(p))).collect());
    sim.clock();
    sense(&o)
}

/// rust-hdl's simulator alone (the frame simulation's speed in it: `examples/sim_speed.rs`).
impl<U: Block + Pins> Cycle for HdlSim<U> {
    fn cycle(&mut self, d: &Drive) -> Result<Sense, String> {
        Ok(cycle_by_name(self, d))
    }
}

/// `raster_top` of one build under Verilator, its ports looked up once and driven with
/// plain integers: the frame simulation of `render --engine rtl` (a million cycles per
/// second and more).
pub struct RasterTopVl {
    vl: VlSim,
    build: Build,
    clock: PortId,
    /// width, height, cull_back, inp$valid, inp_last, mem$ready, mem$rd_z.
    inputs: [PortId; 7],
    /// Per vertex: x, y, z, c0, c1, c2, iw.
    vertices: [[PortId; 7]; 3],
    /// inp$ready, verdict$valid, verdict$code, done, mem$rd_en, mem$rd_addr, mem$wr_en, mem$wr_addr, mem$wr_z, mem$wr_rgb.
    outputs: [PortId; 10],
    /// Pixels a memory word (the width of `mem$wr_en`), and the words of `mem$rd_z`,
    /// `mem$wr_z` and `mem$wr_rgb`.
    lanes: usize,
    words: [Vec<u64>; 3],
    /// The triangle last driven on `inp$v*`: a triangle is offered for many cycles, and its
    /// 21 ports are driven again only when it changes.
    tri: Option<[Vtx; 3]>,
}

impl RasterTopVl {
    /// `vl`, an instance of the whole `raster_top` (`CULL_SORT = 1`, `PIXEL_OUT = 1`) of
    /// build `build`.
    pub fn new(vl: VlSim, build: Build) -> Self {
        let ids = |names: &[&str]| names.iter().map(|n| vl.port(n)).collect::<Vec<_>>();
        let inputs = ids(&["width", "height", "cull_back", "inp$valid", "inp_last", "mem$ready", "mem$rd_z"]);
        let vertices = [0, 1, 2].map(|k| {
            let names = ["x", "y", "z", "c0", "c1", "c2", "iw"].map(|f| format!("inp$v{k}_{f}"));
            names.map(|n| vl.port(&n))
        });
        let outputs = ids(&[&["inp$ready", "verdict$valid", "verdict$code", "done"][..], &REQUEST[..]].concat());
        let words = |id: PortId| vec![0; vl.width(id).div_ceil(64)];
        RasterTopVl {
            clock: vl.port("clock"),
            lanes: vl.width(outputs[6]),
            words: [words(inputs[6]), words(outputs[8]), words(outputs[9])],
            inputs: inputs.try_into().expect("seven inputs"),
            vertices,
            outputs: outputs.try_into().expect("ten outputs"),
            vl,
            build,
            tri: None,
        }
    }

    /// Pixels a memory word: the `LANES` of its vector unit (1 for the scanline method).
    pub fn lanes(&self) -> u32 {
        self.lanes as u32
    }
}

impl Cycle for RasterTopVl {
    fn cycle(&mut self, d: &Drive) -> Result<Sense, String> {
        if d.build != self.build || d.lanes as usize != self.lanes {
            return Err(format!(
                "this raster_top is of build {:?} with {} lanes, not {:?} with {}",
                self.build, self.lanes, d.build, d.lanes
            ));
        }
        let vl = &mut self.vl;
        let [width, height, cull_back, inp_valid, inp_last, mem_ready, rd_z] = self.inputs;
        vl.set_u64(width, d.width as u64);
        vl.set_u64(height, d.height as u64);
        vl.set_u64(cull_back, d.cull_back as u64);
        vl.set_u64(inp_valid, d.inp_valid as u64);
        vl.set_u64(inp_last, d.inp_last as u64);
        vl.set_u64(mem_ready, d.mem_ready as u64);
        let depth = vl.width(rd_z) / self.lanes;
        let [rd_words, z_words, rgb_words] = &mut self.words;
        pack_words(&d.rd_z, depth, self.lanes, rd_words);
        vl.set_words(rd_z, rd_words);
        if self.tri != Some(d.tri) {
            for (v, ids) in d.tri.iter().zip(&self.vertices) {
                // Two's complement, cut to the port's width by `set_u64`.
                for (id, x) in ids.iter().zip([v.x, v.y, v.z, v.c[0], v.c[1], v.c[2], v.iw]) {
                    vl.set_u64(*id, x as u64);
                }
            }
            self.tri = Some(d.tri);
        }
        vl.eval();
        let [inp_ready, verdict_valid, verdict_code, done, rd_en, rd_addr, wr_en, wr_addr, wr_z, wr_rgb] = self.outputs;
        vl.get_words(wr_z, z_words);
        vl.get_words(wr_rgb, rgb_words);
        let s = Sense {
            inp_ready: vl.get_u64(inp_ready) == 1,
            verdict_valid: vl.get_u64(verdict_valid) == 1,
            verdict_code: vl.get_u64(verdict_code) as u8,
            req: Request {
                rd_en: vl.get_u64(rd_en) as u8,
                rd_addr: vl.get_u64(rd_addr) as u32,
                wr_en: vl.get_u64(wr_en) as u8,
                wr_addr: vl.get_u64(wr_addr) as u32,
                wr_z: unpack(z_words, depth, self.lanes),
                wr_rgb: unpack(rgb_words, 3 * CHANNEL, self.lanes),
            },
            done: vl.get_u64(done) == 1,
        };
        // The rising edge. The clock falls with the next cycle's inputs, in that cycle's
        // one settle: nothing in the design acts on a falling edge.
        vl.set_u64(self.clock, 1);
        vl.eval();
        vl.set_u64(self.clock, 0);
        Ok(s)
    }
}

/// `raster_top` of `build` with `K` and `L` as in `UNITS`' defaults, emitted, Verilated
/// (the model is built the first time, under `<target>/verilator/`) and instantiated.
pub fn verilator(build: &Build) -> Result<RasterTopVl, String> {
    verilator_with(build, &[])
}

/// [`verilator`] with parameters `params` (e.g. `K`, `L`) over `UNITS`' defaults.
pub fn verilator_with(build: &Build, params: &[(&str, u64)]) -> Result<RasterTopVl, String> {
    let unit = rtl::Unit::named("raster_top").expect("raster_top is in UNITS");
    let given = params.iter().map(|(k, v)| (k.to_string(), *v));
    let params = unit.params([("N".to_owned(), build.class as u64)].into_iter().chain(given))?;
    Ok(RasterTopVl::new(crate::verilated(unit, &params, Some(&build.formats))?.model()?, *build))
}

/// What one frame is: the screen, the triangles (hardware words) and how to draw them.
pub struct Frame<'a> {
    /// The build of the `raster_top` drawing it.
    pub build: Build,
    pub width: u32,
    pub height: u32,
    pub cull: Cull,
    pub background: [u8; 3],
    pub triangles: &'a [[Vtx; 3]],
    /// Pixels a memory word: the `LANES` of the `raster_top` drawing it.
    pub lanes: u32,
}

/// How the memory behaves.
pub struct MemoryModel<'a> {
    pub read_during_write: ReadDuringWrite,
    /// Whether the memory is ready in cycle `c` (`mem$ready`).
    pub ready: &'a mut dyn FnMut(u64) -> bool,
}

/// A frame drawn, with what happened when.
pub struct FrameOut {
    pub memory: Memory,
    /// Cycles until `done`: the cycle `done` was first high.
    pub cycles: u64,
    /// Per triangle, the cycle `raster_top` took it.
    pub taken: Vec<u64>,
    /// Per triangle, in order, `cull_sort`'s verdict code (`rtl::cull_sort::verdict`).
    pub verdicts: Vec<u8>,
    /// The cycle of each depth read (one per pixel reaching `pixel_out`: a chunk's read
    /// once per lane read), in order.
    pub reads: Vec<u64>,
    /// Cycles the memory was not ready.
    pub stalls: u64,
}

/// Draws `frame` on `dut` (a fresh `raster_top`, or one whose last frame is done), giving
/// up after `max_cycles`.
pub fn draw(dut: &mut dyn Cycle, frame: &Frame, mem: MemoryModel, max_cycles: u64) -> Result<FrameOut, String> {
    assert!(!frame.triangles.is_empty(), "a frame needs a triangle to carry inp_last");
    let zmax = z_max(&frame.build.formats) as u32;
    let size = (frame.width, frame.height);
    let mut memory = Memory::new(frame.build.class, frame.lanes, size, zmax, frame.background, mem.read_during_write);
    let n = frame.triangles.len();
    let (mut taken, mut verdicts, mut reads, mut stalls) = (Vec::new(), Vec::new(), Vec::new(), 0);
    let (build, width, height, cull_back) = (frame.build, frame.width, frame.height, frame.cull == Cull::Back);
    let mut d = Drive { build, width, height, cull_back, lanes: frame.lanes, ..Drive::default() };
    for cycle in 0..max_cycles {
        let next = taken.len();
        d.inp_valid = next < n;
        if d.inp_valid {
            d.tri = frame.triangles[next];
            d.inp_last = next + 1 == n;
        }
        d.mem_ready = (mem.ready)(cycle);
        d.rd_z = memory.rd_z();
        let o = dut.cycle(&d)?;
        if o.done && !d.inp_valid {
            return Ok(FrameOut { memory, cycles: cycle, taken, verdicts, reads, stalls });
        }
        if d.inp_valid && o.inp_ready {
            taken.push(cycle);
        }
        if o.verdict_valid {
            verdicts.push(o.verdict_code);
        }
        if d.mem_ready {
            reads.extend(std::iter::repeat_n(cycle, o.req.rd_en.count_ones() as usize));
        }
        stalls += !d.mem_ready as u64;
        memory.edge(d.mem_ready, &o.req);
    }
    Err(format!("raster_top: no done after {max_cycles} cycles ({} of {n} triangles taken)", taken.len()))
}

/// `raster_top` in rust-hdl with the default parameters of `UNITS` (K, L).
pub fn unit() -> RasterTop {
    let u = rtl::Unit::named("raster_top").expect("raster_top is in UNITS");
    let p = u.params([]).expect("default parameters");
    RasterTop::new(p["K"] as usize, p["L"] as usize, &rtl::switch::Parts::ALL)
        .expect("the default parameters are supported")
}

/// Writes `frame` and the memory writes `writes` as the vector file of the Icarus Verilog
/// bench `testbenches/iverilog/raster_top_tb.v` (its header gives the format).
pub fn write_vectors(path: &Path, frame: &Frame, writes: &[Pixel]) -> std::io::Result<()> {
    use std::fmt::Write as _;
    let w = InputWidths::of(&frame.build);
    let mut text = format!(
        "{:x} {:x} {:x} {:x}\n",
        frame.width,
        frame.height,
        (frame.cull == Cull::Back) as u8,
        frame.triangles.len()
    );
    for t in frame.triangles {
        let words: Vec<String> = t
            .iter()
            .flat_map(|v| {
                let c = v.c.map(|c| low(w.color, c));
                [low(w.xy, v.x), low(w.xy, v.y), low(w.z, v.z), c[0], c[1], c[2], low(w.inv_w, v.iw)]
            })
            .map(|w| format!("{w:x}"))
            .collect();
        writeln!(text, "{}", words.join(" ")).expect("writing to a String");
    }
    writeln!(text, "{:x}", writes.len()).expect("writing to a String");
    for p in writes {
        let rgb = (p.rgb[0] as u32) << (2 * CHANNEL) | (p.rgb[1] as u32) << CHANNEL | p.rgb[2] as u32;
        writeln!(text, "{:x} {:x} {rgb:x}", (p.y << frame.build.class) | p.x, p.z).expect("writing to a String");
    }
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::write(path, text)
}

/// Cycle counts of a frame, measured on the RTL.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// Cycles until `done`, and what `model::cycles::scanline_frame` predicts.
    pub cycles: u64,
    pub predicted: u64,
    pub triangles: usize,
    /// Triangles that passed `cull_sort`.
    pub drawn: usize,
    /// Pixels that reached `pixel_out`, and those written (passed the depth test).
    pub fragments: u64,
    pub written: u64,
    /// Per drawn triangle with a pixel: cycles from taking it to its first pixel's depth
    /// read in `pixel_out` (min, median, max).
    pub latency: Option<(u64, u64, u64)>,
    /// Cycles between taking one triangle and the next (mean, max).
    pub interval: (f64, u64),
}

impl Report {
    /// `out` of `prep`'s frame.
    pub fn of(out: &FrameOut, prep: &model::raster_top::RasterTopOut) -> Report {
        let mut latency = Vec::new();
        let mut first = 0;
        for (i, &n) in prep.fragments.iter().enumerate() {
            if n > 0 && first < out.reads.len() {
                latency.push(out.reads[first] - out.taken[i]);
            }
            first += n;
        }
        latency.sort_unstable();
        let gaps: Vec<u64> = out.taken.windows(2).map(|w| w[1] - w[0]).collect();
        Report {
            cycles: out.cycles,
            predicted: prep.cycles(),
            triangles: out.taken.len(),
            drawn: out.verdicts.iter().filter(|&&v| v as u64 == rtl::cull_sort::verdict::PASSED).count(),
            fragments: out.reads.len() as u64,
            written: out.memory.writes,
            latency: (!latency.is_empty())
                .then(|| (latency[0], latency[latency.len() / 2], latency[latency.len() - 1])),
            interval: (
                gaps.iter().sum::<u64>() as f64 / gaps.len().max(1) as f64,
                gaps.iter().copied().max().unwrap_or(0),
            ),
        }
    }

    /// Pixels written per clock.
    pub fn pixels_per_clock(&self) -> f64 {
        self.written as f64 / self.cycles.max(1) as f64
    }
}
