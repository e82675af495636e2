//! `gpu_top` in a system, driven as a host drives it: the registers written over AXI4-Lite,
//! START, the vertex buffer read from one memory (`model::read_memory`), the depth and
//! colour buffers in two others (`model::word_memory`), until the interrupt; then
//! `STATUS`, `FRAME_CYCLES` and `TRIANGLES` read back. The frame simulation of `edgepaint
//! render --engine rtl` and of the `gpu_top` tests (the README's driver sequence).

use crate::streams::as_pins;
use crate::{Outputs, PortDir, Sim, Value, VlSim};
use model::gpu_regs::Reg;
use model::read_memory::{ReadMemory, ReadRequest};
use model::word_memory::{WordMemory, WordRequest};

/// Where the buffers sit on the bus.
pub const VB_BASE: u32 = 0x1000;
pub const DEPTH_BASE: u32 = 0x10_0000;
pub const COLOR_BASE: u32 = 0x40_0000;
/// What the colour and depth memories hold before any write.
pub const FILL: u32 = 0xdead_beef;

/// One cycle of the core in a simulator: drives the inputs named, settles, returns every
/// output, clocks.
pub type Step = Box<dyn FnMut(&[(&str, Value)]) -> Outputs>;

/// `gpu_top` with its defaults (`rtl::UNITS`) in Verilator, built the first time (cached
/// under `<target>/verilator/`).
pub fn verilator() -> Result<Step, String> {
    let unit = rtl::Unit::named("gpu_top").expect("gpu_top is in UNITS");
    let params = unit.params([])?;
    Ok(verilator_step(crate::verilated(unit, &params, None)?.model()?))
}

/// A [`Step`] of `vl`.
pub fn verilator_step(mut vl: VlSim) -> Step {
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

/// How the memories answer: `latency` cycles late, each channel held back in a cycle
/// when its `stall` says so (vertex buffer, depth, colour).
pub struct Pace<'a> {
    pub latency: u32,
    pub stalls: [Box<dyn FnMut() -> bool + 'a>; 3],
}

impl Pace<'_> {
    /// Latency 0, nothing held back.
    pub fn at_once() -> Self {
        Pace { latency: 0, stalls: [(); 3].map(|_| Box::new(|| false) as Box<dyn FnMut() -> bool>) }
    }
}

/// The core with its memories.
pub struct Soc<'a> {
    step: Step,
    pub vb: ReadMemory<'a>,
    pub depth: WordMemory<'a>,
    pub color: WordMemory<'a>,
    /// The buffers' size in pixels (`SCREEN`); rows are `4 * width` bytes apart.
    pub screen: (u32, u32),
    pub cycle: u64,
}

/// A register access of the host: a write (data) or a read.
#[derive(Clone, Copy, Debug)]
pub enum Access {
    Write(Reg, u32),
    Read(Reg),
}

/// A frame's end as the host reads it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameEnd {
    pub status: u32,
    pub cycles: u32,
    pub triangles: u32,
}

impl<'a> Soc<'a> {
    /// The vertex buffer `vb` at [`VB_BASE`], depth and colour buffers of `screen` pixels
    /// at [`DEPTH_BASE`] and [`COLOR_BASE`] filled with [`FILL`].
    pub fn new(step: Step, vb: &'a [u8], screen: (u32, u32), pace: Pace<'a>) -> Soc<'a> {
        let words = (screen.0 * screen.1) as usize;
        let [a, b, c] = pace.stalls;
        Soc {
            step,
            vb: ReadMemory::new(vb, VB_BASE, rtl::command_parser::BEAT_BYTES, pace.latency, a),
            depth: WordMemory::new(vec![FILL; words], DEPTH_BASE, pace.latency, b),
            color: WordMemory::new(vec![FILL; words], COLOR_BASE, pace.latency, c),
            screen,
            cycle: 0,
        }
    }

    /// The simulator, for the next system.
    pub fn into_step(self) -> Step {
        self.step
    }

    /// One cycle with the host's pins `host`: the memories answer, the outputs are read,
    /// the clock ticks.
    pub fn cycle(&mut self, host: &[(&str, Value)]) -> Outputs {
        let bit = |b: bool| Value::new(1, b as u128);
        let (r, z, c) = (self.vb.response(), self.depth.response(), self.color.response());
        let mut pins: Vec<(String, Value)> = host.iter().map(|(n, v)| (n.to_string(), v.clone())).collect();
        pins.extend([
            ("vb$ar_ready".into(), bit(r.ar_ready)),
            ("vb$r_valid".into(), bit(r.r_valid)),
            ("vb$r_data".into(), Value::new(128, r.data_128())),
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

    /// One register access, from offer to answer: the read's data (0 for a write), or
    /// an error if the register block answers one.
    pub fn access(&mut self, a: Access) -> Result<u32, String> {
        let bit = |b: bool| Value::new(1, b as u128);
        let (addr, data, write) = match a {
            Access::Write(r, d) => (r as u32, d, true),
            Access::Read(r) => (r as u32, 0, false),
        };
        let offer = [
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
        let (valid, resp) = if write { ("host$b_valid", "host$b_resp") } else { ("host$r_valid", "host$r_resp") };
        loop {
            let o = self.cycle(&idle);
            if o.get(valid).bit(0) {
                return match o.get(resp).to_u128() {
                    0 => Ok(if write { 0 } else { o.get("host$r_data").to_u128() as u32 }),
                    e => Err(format!("{a:?} answered {e}")),
                };
            }
        }
    }

    /// The README's driver sequence for a frame of the buffer at [`VB_BASE`]: the buffers'
    /// addresses, pitches and size, then START (with CLEAR if `clear`) and IRQ_EN.
    pub fn registers(&self, clear: bool) -> Vec<(Reg, u32)> {
        let (width, height) = self.screen;
        vec![
            (Reg::VbAddr, VB_BASE),
            (Reg::ColorBase, COLOR_BASE),
            (Reg::ColorPitch, 4 * width),
            (Reg::DepthBase, DEPTH_BASE),
            (Reg::DepthPitch, 4 * width),
            (Reg::Screen, height << 16 | width),
            (Reg::Control, (clear as u32) << 1 | 4 | 1),
        ]
    }

    /// A frame: [`Soc::registers`] written, cycles until the interrupt (an error after
    /// `limit`), the interrupt cleared, then `STATUS`, `FRAME_CYCLES` and `TRIANGLES` read.
    pub fn frame(&mut self, clear: bool, limit: u64) -> Result<FrameEnd, String> {
        self.frame_with(&self.registers(clear), limit)
    }

    /// [`Soc::frame`] with the register writes `writes` (the last one starting the frame).
    pub fn frame_with(&mut self, writes: &[(Reg, u32)], limit: u64) -> Result<FrameEnd, String> {
        for &(r, v) in writes {
            self.access(Access::Write(r, v))?;
        }
        let start = self.cycle;
        let none: [(&str, Value); 0] = [];
        while !self.cycle(&none).get("irq").bit(0) {
            if self.cycle - start >= limit {
                let status = self.access(Access::Read(Reg::Status))?;
                let t = self.access(Access::Read(Reg::Triangles))?;
                return Err(format!(
                    "gpu_top: no interrupt in {limit} cycles: STATUS {status:#x}, {t} triangles, {} depth writes, {} \
                     colour writes",
                    self.depth.written.len(),
                    self.color.written.len()
                ));
            }
        }
        self.access(Access::Write(Reg::Irq, 1))?;
        Ok(FrameEnd {
            status: self.access(Access::Read(Reg::Status))?,
            cycles: self.access(Access::Read(Reg::FrameCycles))?,
            triangles: self.access(Access::Read(Reg::Triangles))?,
        })
    }
}
