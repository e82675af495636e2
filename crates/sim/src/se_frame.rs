//! Whole frames through `raster_top`'s SE back end (`METHOD = 2`: the scanline front end,
//! `se_cmd` and `ENGINES` shading engines) under Verilator, with the depth and colour
//! buffers in Rust behind its banked memory port (`rtl::links::SeMemory`): lane 4 i + k of a
//! word is pixel 64 i + 4 j + k of row y at address `{y, j}`; a read's data is given in the
//! cycle it is asked for (zero past the screen's right edge, as `model::se::array` reads),
//! the lanes of a write are made at the rising edge. Cycle 0 is the first cycle the first
//! triangle is offered, triangles back to back, as `model::cycles::se_frame` assumes.

use crate::frame::{triangle_pins, Frame};
use crate::memory::{field, pack_words, Memory, ReadDuringWrite};
use crate::streams::unsigned;
use crate::{PortId, VlSim};
use fx::Build;
use model::cull_sort::{z_max, Cull};
use rtl::widths::CHANNEL;

/// Pixels an engine covers, and port groups (of four) it reads and writes.
const P: u32 = 64;
const GROUP_BITS: u32 = 4;

/// `raster_top` with `METHOD = 2` of one build under Verilator, its ports looked up once.
pub struct RasterTopSeVl {
    vl: VlSim,
    build: Build,
    /// Engines (a quarter of the lanes of `mem$wr_en`).
    engines: u32,
    clock: PortId,
    /// width, height, cull_back, inp$valid, inp_last.
    inputs: [PortId; 5],
    /// inp$ready, verdict$valid, verdict$code, done, mem$rd, mem$rd_addr, mem$wr, mem$wr_addr.
    outputs: [PortId; 8],
    rd_z: PortId,
    wr_en: PortId,
    wr_z: PortId,
    wr_rgb: PortId,
    /// The words of `mem$rd_z`, `mem$wr_en`, `mem$wr_z` and `mem$wr_rgb`.
    words: [Vec<u64>; 4],
}

impl RasterTopSeVl {
    /// `vl`, an instance of `raster_top` with `METHOD = 2` of build `build`.
    pub fn new(vl: VlSim, build: Build) -> Self {
        let ids = |names: &[&str]| names.iter().map(|n| vl.port(n)).collect::<Vec<_>>();
        let inputs = ids(&["width", "height", "cull_back", "inp$valid", "inp_last"]);
        let outputs = ids(&[
            "inp$ready",
            "verdict$valid",
            "verdict$code",
            "done",
            "mem$rd",
            "mem$rd_addr",
            "mem$wr",
            "mem$wr_addr",
        ]);
        let [rd_z, wr_en, wr_z, wr_rgb] = ["mem$rd_z", "mem$wr_en", "mem$wr_z", "mem$wr_rgb"].map(|n| vl.port(n));
        let words = [rd_z, wr_en, wr_z, wr_rgb].map(|id| vec![0; vl.width(id).div_ceil(64)]);
        RasterTopSeVl {
            engines: vl.width(wr_en) as u32 / 4,
            clock: vl.port("clock"),
            inputs: inputs.try_into().expect("five inputs"),
            outputs: outputs.try_into().expect("eight outputs"),
            rd_z,
            wr_en,
            wr_z,
            wr_rgb,
            words,
            vl,
            build,
        }
    }

    /// Engines in the array: screens up to 64 columns each.
    pub fn engines(&self) -> u32 {
        self.engines
    }
}

/// `raster_top` with `METHOD = 2` and `engines` engines at the default build, emitted,
/// Verilated (once, cached under the target directory) and instantiated.
pub fn verilator(engines: u32) -> Result<RasterTopSeVl, String> {
    let build = Build::default();
    let unit = rtl::Unit::named("raster_top").expect("raster_top is in UNITS");
    let given = [("METHOD", 2), ("ENGINES", engines as u64)].map(|(k, v)| (k.to_string(), v));
    let params = unit.params([("N".to_owned(), build.class as u64)].into_iter().chain(given))?;
    Ok(RasterTopSeVl::new(crate::verilated(unit, &params, Some(&build.formats))?.model()?, build))
}

/// A frame drawn by the SE back end.
pub struct SeFrameOut {
    pub memory: Memory,
    /// Cycles until `done`: the cycle `done` was first high.
    pub cycles: u64,
    /// Per triangle, the cycle `raster_top` took it.
    pub taken: Vec<u64>,
    /// Per triangle, in order, `cull_sort`'s verdict code.
    pub verdicts: Vec<u8>,
    /// Cycles with a read, and with a write.
    pub reads: u64,
    pub writes: u64,
}

/// Draws `frame` on `dut` (fresh, or done with its last frame), giving up after
/// `max_cycles`; an error too for a screen wider than the engines reach or a write past
/// its right edge.
pub fn draw(dut: &mut RasterTopSeVl, frame: &Frame, max_cycles: u64) -> Result<SeFrameOut, String> {
    assert!(!frame.triangles.is_empty(), "a frame needs a triangle to carry inp_last");
    if frame.build != dut.build {
        return Err(format!("this raster_top is of build {:?}, not {:?}", dut.build, frame.build));
    }
    let (width, height) = (frame.width, frame.height);
    if width > P * dut.engines {
        return Err(format!("{} engines draw screens up to {} columns, not {width}", dut.engines, P * dut.engines));
    }
    let lanes = 4 * dut.engines as usize;
    let depth = dut.vl.width(dut.rd_z) / lanes;
    let zmax = z_max(&frame.build.formats) as u32;
    let mut memory = Memory::new(frame.build.class, 1, (width, height), zmax, frame.background, ReadDuringWrite::Old);
    let pins: Vec<Vec<(PortId, u64)>> = frame
        .triangles
        .iter()
        .map(|t| {
            triangle_pins(&frame.build, t)
                .into_iter()
                .map(|(name, v)| (dut.vl.port(&name), unsigned(&v) as u64))
                .collect()
        })
        .collect();
    let n = frame.triangles.len();
    let (mut taken, mut verdicts, mut reads, mut writes) = (Vec::new(), Vec::new(), 0, 0);
    let mut rd_lanes = vec![0u32; lanes];
    let [w, h, cull_back, inp_valid, inp_last] = dut.inputs;
    for cycle in 0..max_cycles {
        let vl = &mut dut.vl;
        let next = taken.len();
        vl.set_u64(w, width as u64);
        vl.set_u64(h, height as u64);
        vl.set_u64(cull_back, (frame.cull == Cull::Back) as u64);
        vl.set_u64(inp_valid, (next < n) as u64);
        vl.set_u64(inp_last, (next + 1 == n) as u64);
        for &(id, v) in &pins[next.min(n - 1)] {
            vl.set_u64(id, v);
        }
        vl.eval();
        let [inp_ready, verdict_valid, verdict_code, done, rd, rd_addr, wr, wr_addr] = dut.outputs;
        // The engines' old-z load: the word asked for, in this cycle.
        if vl.get_u64(rd) == 1 {
            let addr = vl.get_u64(rd_addr) as u32;
            let (y, j) = (addr >> GROUP_BITS, addr & ((1 << GROUP_BITS) - 1));
            for (l, z) in rd_lanes.iter_mut().enumerate() {
                let x = P * (l as u32 / 4) + 4 * j + l as u32 % 4;
                *z = if x < width && y < height { memory.depth[(y * width + x) as usize] } else { 0 };
            }
            pack_words(&rd_lanes, depth, lanes, &mut dut.words[0]);
            vl.set_words(dut.rd_z, &dut.words[0]);
            vl.eval();
            reads += 1;
        }
        if vl.get_u64(done) == 1 && next == n {
            return Ok(SeFrameOut { memory, cycles: cycle, taken, verdicts, reads, writes });
        }
        if next < n && vl.get_u64(inp_ready) == 1 {
            taken.push(cycle);
        }
        if vl.get_u64(verdict_valid) == 1 {
            verdicts.push(vl.get_u64(verdict_code) as u8);
        }
        let write = (vl.get_u64(wr) == 1).then(|| vl.get_u64(wr_addr) as u32);
        if write.is_some() {
            let [_, en, z, rgb] = &mut dut.words;
            vl.get_words(dut.wr_en, en);
            vl.get_words(dut.wr_z, z);
            vl.get_words(dut.wr_rgb, rgb);
        }
        vl.set_u64(dut.clock, 1);
        vl.eval();
        vl.set_u64(dut.clock, 0);
        if let Some(addr) = write {
            writes += 1;
            let (y, j) = (addr >> GROUP_BITS, addr & ((1 << GROUP_BITS) - 1));
            let [_, en, z, rgb] = &dut.words;
            for l in (0..lanes).filter(|&l| en[l / 64] >> (l % 64) & 1 == 1) {
                let x = P * (l as u32 / 4) + 4 * j + l as u32 % 4;
                if x >= width || y >= height {
                    return Err(format!("cycle {cycle}: a write of pixel ({x}, {y}), off the {width}x{height} screen"));
                }
                let at = (y * width + x) as usize;
                let c = field(rgb, 3 * CHANNEL, l);
                memory.depth[at] = field(z, depth, l);
                memory.rgb[at] = [c >> (2 * CHANNEL), c >> CHANNEL, c].map(|c| c as u8);
                memory.written[at] = true;
                memory.writes += 1;
            }
        }
    }
    Err(format!("raster_top (SE): no done after {max_cycles} cycles ({} of {n} triangles taken)", taken.len()))
}
