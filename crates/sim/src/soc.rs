//! `gpu_top` in a system, driven as a host drives it: the registers written over AXI4-Lite,
//! START, the vertex buffer read from one memory (`model::read_memory`), the depth and
//! colour buffers in two others (`model::word_memory`), until the interrupt; then
//! `STATUS`, `FRAME_CYCLES` and `TRIANGLES` read back. The frame simulation of `edgepaint
//! render --engine rtl` and of the `gpu_top` tests (the README's driver sequence).

use crate::{Outputs, PortId, Value, VlSim};
use model::gpu_regs::Reg;
use model::read_memory::{ReadMemory, ReadRequest, ReadResponse};
use model::word_memory::{WordMemory, WordRequest, WordResponse};

/// Where the buffers sit on the bus.
pub const VB_BASE: u32 = 0x1000;
pub const DEPTH_BASE: u32 = 0x10_0000;
pub const COLOR_BASE: u32 = 0x40_0000;
/// What the colour and depth memories hold before any write.
pub const FILL: u32 = 0xdead_beef;

/// What the system drives into `gpu_top` in one cycle: the host's AXI4-Lite offer (every
/// write strobe set) and the three memories' sides of their buses.
#[derive(Clone, Copy, Debug, Default)]
pub struct Drive {
    /// A write's address and data, a read's address, offered.
    pub host_aw: Option<u32>,
    pub host_w: Option<u32>,
    pub host_ar: Option<u32>,
    pub vb: ReadResponse,
    pub depth: WordResponse,
    pub color: WordResponse,
}

/// What `gpu_top` drives in one cycle, sampled before the clock edge.
#[derive(Clone, Copy, Debug, Default)]
pub struct Sense {
    pub host_w_ready: bool,
    pub host_ar_ready: bool,
    /// A write's response, a read's data and response, offered.
    pub host_b: Option<u32>,
    pub host_r: Option<(u32, u32)>,
    pub irq: bool,
    pub vb_ar: Option<ReadRequest>,
    pub vb_r_ready: bool,
    pub depth: WordRequest,
    pub color: WordRequest,
}

/// One clock of `gpu_top` in a simulator: drive, settle, sample, clock.
pub trait Core {
    fn cycle(&mut self, d: &Drive) -> Result<Sense, String>;
}

/// `gpu_top`'s inputs that [`Drive`] sets, with their widths, in [`input_values`]' order.
/// (`host$b_ready` and `host$r_ready` are always high: the host takes every answer.)
const INPUTS: [(&str, usize); 25] = [
    ("host$aw_valid", 1),
    ("host$aw_addr", 6),
    ("host$w_valid", 1),
    ("host$w_data", 32),
    ("host$w_strb", 4),
    ("host$b_ready", 1),
    ("host$ar_valid", 1),
    ("host$ar_addr", 6),
    ("host$r_ready", 1),
    ("vb$ar_ready", 1),
    ("vb$r_valid", 1),
    ("vb$r_data", 128),
    ("vb$r_resp", 2),
    ("zr$ar_ready", 1),
    ("zr$r_valid", 1),
    ("zr$r_data", 32),
    ("zr$r_resp", 2),
    ("zw$aw_ready", 1),
    ("zw$w_ready", 1),
    ("zw$b_valid", 1),
    ("zw$b_resp", 2),
    ("cw$aw_ready", 1),
    ("cw$w_ready", 1),
    ("cw$b_valid", 1),
    ("cw$b_resp", 2),
];

/// The values of [`INPUTS`] for `d`.
fn input_values(d: &Drive) -> [u128; 25] {
    let resp = |error: bool| if error { 2 } else { 0 };
    let (z, c, r) = (&d.depth, &d.color, &d.vb);
    let on = |b: bool| b as u128;
    [
        on(d.host_aw.is_some()),
        d.host_aw.unwrap_or(0).into(),
        on(d.host_w.is_some()),
        d.host_w.unwrap_or(0).into(),
        15,
        1,
        on(d.host_ar.is_some()),
        d.host_ar.unwrap_or(0).into(),
        1,
        on(r.ar_ready),
        on(r.r_valid),
        r.data_128(),
        resp(r.r_error),
        on(z.ar_ready),
        on(z.r_valid),
        z.r_data.into(),
        resp(z.r_error),
        on(z.aw_ready),
        on(z.w_ready),
        on(z.b_valid),
        resp(z.b_error),
        on(c.aw_ready),
        on(c.w_ready),
        on(c.b_valid),
        resp(c.b_error),
    ]
}

/// `gpu_top`'s outputs that [`Sense`] reads, in [`sense`]'s order.
const OUTPUTS: [&str; 23] = [
    "host$w_ready",
    "host$ar_ready",
    "host$b_valid",
    "host$b_resp",
    "host$r_valid",
    "host$r_data",
    "host$r_resp",
    "irq",
    "vb$ar_valid",
    "vb$ar_addr",
    "vb$ar_len",
    "vb$r_ready",
    "zr$ar_valid",
    "zr$ar_addr",
    "zw$aw_valid",
    "zw$aw_addr",
    "zw$w_valid",
    "zw$w_data",
    "cw$aw_valid",
    "cw$aw_addr",
    "cw$w_valid",
    "cw$w_data",
    "host$aw_ready",
];

/// [`OUTPUTS`]' values as a [`Sense`].
fn sense(v: [u128; 23]) -> Sense {
    let on = |i: usize| v[i] == 1;
    let word = |i: usize| v[i] as u32;
    let write = |valid: usize| WordRequest {
        ar: None,
        aw: on(valid).then(|| word(valid + 1)),
        w: on(valid + 2).then(|| word(valid + 3)),
        r_ready: true,
        b_ready: true,
    };
    Sense {
        host_w_ready: on(0),
        host_ar_ready: on(1),
        host_b: on(2).then(|| word(3)),
        host_r: on(4).then(|| (word(5), word(6))),
        irq: on(7),
        vb_ar: on(8).then(|| ReadRequest { addr: word(9), beats: word(10) + 1 }),
        vb_r_ready: on(11),
        depth: WordRequest { ar: on(12).then(|| word(13)), ..write(14) },
        color: write(18),
    }
}

/// One cycle of a simulator driven by port name: drives the inputs named, returns every
/// output, clocks.
pub type NamedCycle = dyn FnMut(&[(&str, Value)]) -> Result<Outputs, String>;

/// `gpu_top` in any simulator driven by port name (rust-hdl and Verilator in lockstep in
/// the tests).
pub struct ByName(pub Box<NamedCycle>);

impl Core for ByName {
    fn cycle(&mut self, d: &Drive) -> Result<Sense, String> {
        let values = input_values(d);
        let pins: Vec<(&str, Value)> = INPUTS.iter().zip(values).map(|(&(n, w), v)| (n, Value::new(w, v))).collect();
        let o = (self.0)(&pins)?;
        Ok(sense(OUTPUTS.map(|n| o.get(n).to_u128())))
    }
}

/// `gpu_top` under Verilator, its ports looked up once: the frame simulation of `render
/// --engine rtl`.
pub struct GpuTopVl {
    vl: VlSim,
    clock: PortId,
    inputs: [PortId; 25],
    outputs: [PortId; 23],
}

impl GpuTopVl {
    pub fn new(vl: VlSim) -> GpuTopVl {
        GpuTopVl {
            clock: vl.port("clock"),
            inputs: INPUTS.map(|(n, _)| vl.port(n)),
            outputs: OUTPUTS.map(|n| vl.port(n)),
            vl,
        }
    }
}

impl Core for GpuTopVl {
    fn cycle(&mut self, d: &Drive) -> Result<Sense, String> {
        for ((id, &(_, width)), v) in self.inputs.iter().zip(&INPUTS).zip(input_values(d)) {
            if width > 64 {
                self.vl.set_u128(*id, v);
            } else {
                self.vl.set_u64(*id, v as u64);
            }
        }
        self.vl.eval();
        // Every output read is at most 32 bits wide.
        let s = sense(self.outputs.map(|id| u128::from(self.vl.get_u64(id))));
        // The rising edge; the clock falls with the next cycle's inputs (nothing acts on
        // a falling edge).
        self.vl.set_u64(self.clock, 1);
        self.vl.eval();
        self.vl.set_u64(self.clock, 0);
        Ok(s)
    }
}

/// `gpu_top` with its defaults (`rtl::UNITS`) in Verilator, built the first time (cached
/// under `<target>/verilator/`).
pub fn verilator() -> Result<Box<dyn Core>, String> {
    let unit = rtl::Unit::named("gpu_top").expect("gpu_top is in UNITS");
    let params = unit.params([])?;
    Ok(Box::new(GpuTopVl::new(crate::verilated(unit, &params, None)?.model()?)))
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
    core: Box<dyn Core>,
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
    pub fn new(core: Box<dyn Core>, vb: &'a [u8], screen: (u32, u32), pace: Pace<'a>) -> Soc<'a> {
        let words = (screen.0 * screen.1) as usize;
        let [a, b, c] = pace.stalls;
        Soc {
            core,
            vb: ReadMemory::new(vb, VB_BASE, rtl::command_parser::BEAT_BYTES, pace.latency, a),
            depth: WordMemory::new(vec![FILL; words], DEPTH_BASE, pace.latency, b),
            color: WordMemory::new(vec![FILL; words], COLOR_BASE, pace.latency, c),
            screen,
            cycle: 0,
        }
    }

    /// The simulator, for the next system.
    pub fn into_core(self) -> Box<dyn Core> {
        self.core
    }

    /// One cycle with the host offering `host` (a [`Drive`] whose memory sides are
    /// ignored): the memories answer, the outputs are sampled, the clock ticks.
    pub fn cycle(&mut self, host: &Drive) -> Result<Sense, String> {
        let d = Drive { vb: self.vb.response(), depth: self.depth.response(), color: self.color.response(), ..*host };
        let o = self.core.cycle(&d)?;
        self.vb.clock(o.vb_ar, o.vb_r_ready);
        self.depth.clock(&o.depth);
        self.color.clock(&o.color);
        self.cycle += 1;
        Ok(o)
    }

    /// One register access, from offer to answer: the read's data (0 for a write), or
    /// an error if the register block answers one.
    pub fn access(&mut self, a: Access) -> Result<u32, String> {
        let offer = match a {
            Access::Write(r, d) => Drive { host_aw: Some(r as u32), host_w: Some(d), ..Drive::default() },
            Access::Read(r) => Drive { host_ar: Some(r as u32), ..Drive::default() },
        };
        let write = matches!(a, Access::Write(..));
        while !{
            let o = self.cycle(&offer)?;
            if write {
                o.host_w_ready
            } else {
                o.host_ar_ready
            }
        } {}
        loop {
            let o = self.cycle(&Drive::default())?;
            let answer = if write { o.host_b.map(|resp| (0, resp)) } else { o.host_r };
            if let Some((data, resp)) = answer {
                return match resp {
                    0 => Ok(data),
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
        while !self.cycle(&Drive::default())?.irq {
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
