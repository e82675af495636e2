//! `gpu_regs`: the register block a host drives `gpu_top` through, an AXI4-Lite slave,
//! cycle by cycle. Mirrors `rtl::gpu_regs` on every cycle.
//!
//! **The bus.** 32-bit data, byte addresses of [`ADDR_BITS`] bits (the low two ignored).
//! A write is taken when its address and its data are both offered and no response is
//! waiting (`aw_ready` and `w_ready` rise together), its response comes the next cycle and
//! is held until taken; a read is taken when no read data are waiting, its data come the
//! next cycle and are held until taken (a read taken in the cycle a write of its register is
//! taken returns the register before the write). A write's strobes pick the bytes it writes. An
//! address outside the map answers SLVERR (reads return 0); a write to a read-only register
//! answers OKAY and changes nothing. AWPROT and ARPROT are not ports: every access is
//! treated alike.
//!
//! **The map** ([`Reg`]): identification, control (start, clear, interrupt enable),
//! status, the frame-done interrupt (write 1 to clear), the vertex buffer's address, the
//! colour and depth buffers' bases and pitches, the buffers' size, and the last frame's
//! cycles and triangles.

/// Bits of a register address.
pub const ADDR_BITS: u32 = 6;

/// `ID`'s value: "EP", the map's version 2, the hardware's size class.
pub fn id(class: u32) -> u32 {
    u32::from_be_bytes([b'E', b'P', 2, class as u8])
}

/// The registers, by byte address.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reg {
    /// Read only: [`id`].
    Id = 0x00,
    /// Bit 0 START: writing 1 starts a frame (`start` high the next cycle; `gpu_top` takes
    /// it when idle); reads 0. Bit 1 CLEAR: clear the buffers when a frame starts. Bit 2
    /// IRQ_EN: raise `irq` while a frame-done interrupt is pending.
    Control = 0x04,
    /// Read only: `status` as `gpu_top` gives it.
    Status = 0x08,
    /// Bit 0: a frame ended since this bit was last cleared (by writing 1).
    Irq = 0x0c,
    VbAddr = 0x10,
    ColorBase = 0x14,
    /// Bytes per row of the colour buffer (16 bits).
    ColorPitch = 0x18,
    DepthBase = 0x1c,
    /// Bytes per row of the depth buffer (16 bits).
    DepthPitch = 0x20,
    /// Read only: cycles from the last frame's start to its end.
    FrameCycles = 0x24,
    /// Read only: triangles the last frame handed to the rasterizer.
    Triangles = 0x28,
    /// The size of the colour and depth buffers in pixels: width in bits 0-15, height in
    /// bits 16-31. A frame whose header asks for a wider or taller screen, or for rows
    /// longer than a pitch holds, ends with fault `SCREEN` before any pixel is written
    /// (`gpu_top`), so that no buffer asks the core to write outside the buffers.
    Screen = 0x2c,
}

impl Reg {
    /// Every register, in address order.
    pub const ALL: [Reg; 12] = [
        Reg::Id,
        Reg::Control,
        Reg::Status,
        Reg::Irq,
        Reg::VbAddr,
        Reg::ColorBase,
        Reg::ColorPitch,
        Reg::DepthBase,
        Reg::DepthPitch,
        Reg::FrameCycles,
        Reg::Triangles,
        Reg::Screen,
    ];

    /// The register at byte address `addr` (its low two bits ignored).
    pub fn at(addr: u32) -> Option<Reg> {
        Reg::ALL.into_iter().find(|r| *r as u32 == addr & !3 & ((1 << ADDR_BITS) - 1))
    }

    /// The bits a write can change.
    fn writable(self) -> u32 {
        match self {
            Reg::Control => 0b110,
            Reg::VbAddr | Reg::ColorBase | Reg::DepthBase | Reg::Screen => u32::MAX,
            Reg::ColorPitch | Reg::DepthPitch => 0xffff,
            _ => 0,
        }
    }
}

/// AXI4-Lite's responses.
pub const OKAY: u8 = 0;
pub const SLVERR: u8 = 2;

/// The unit's inputs, one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Inputs {
    /// A write address, write data with its strobes, a read address offered.
    pub aw: Option<u32>,
    pub w: Option<(u32, u8)>,
    pub ar: Option<u32>,
    pub b_ready: bool,
    pub r_ready: bool,
    /// From `gpu_top`: `STATUS`, and the last frame's cycles and triangles.
    pub status: u32,
    pub frame_cycles: u32,
    pub triangles: u32,
    /// A frame ended this cycle.
    pub done: bool,
}

/// The unit's outputs, one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outputs {
    /// `aw_ready` and `w_ready` (equal), `ar_ready`.
    pub w_ready: bool,
    pub ar_ready: bool,
    /// The write response waiting, and the read data with their response.
    pub b: Option<u8>,
    pub r: Option<(u32, u8)>,
    /// To `gpu_top`.
    pub start: bool,
    pub clear: bool,
    pub irq: bool,
    pub vb_addr: u32,
    pub color_base: u32,
    pub color_pitch: u16,
    pub depth_base: u32,
    pub depth_pitch: u16,
    pub screen: u32,
}

/// The unit's registers.
#[derive(Clone, Debug)]
pub struct GpuRegs {
    class: u32,
    /// The read-write registers' values, by [`Reg`] (read-only ones stay 0).
    values: [u32; Reg::ALL.len()],
    start: bool,
    pending: bool,
    b: Option<u8>,
    r: Option<(u32, u8)>,
}

impl GpuRegs {
    /// The block of hardware of size class `class`, just out of reset: every register 0.
    pub fn new(class: u32) -> GpuRegs {
        GpuRegs { class, values: [0; Reg::ALL.len()], start: false, pending: false, b: None, r: None }
    }

    fn value(&self, r: Reg) -> u32 {
        self.values[Reg::ALL.iter().position(|x| *x == r).expect("a register")]
    }

    /// What a read of `r` returns with inputs `i`.
    fn read(&self, r: Reg, i: &Inputs) -> u32 {
        match r {
            Reg::Id => id(self.class),
            Reg::Status => i.status,
            Reg::Irq => self.pending as u32,
            Reg::FrameCycles => i.frame_cycles,
            Reg::Triangles => i.triangles,
            _ => self.value(r),
        }
    }

    /// What the unit drives this cycle (`aw_ready` and `w_ready` depend on the offer).
    pub fn outputs(&self, i: &Inputs) -> Outputs {
        let control = self.value(Reg::Control);
        Outputs {
            w_ready: self.takes_write(i),
            ar_ready: self.r.is_none(),
            b: self.b,
            r: self.r,
            start: self.start,
            clear: control & 2 != 0,
            irq: control & 4 != 0 && self.pending,
            vb_addr: self.value(Reg::VbAddr),
            color_base: self.value(Reg::ColorBase),
            color_pitch: self.value(Reg::ColorPitch) as u16,
            depth_base: self.value(Reg::DepthBase),
            depth_pitch: self.value(Reg::DepthPitch) as u16,
            screen: self.value(Reg::Screen),
        }
    }

    /// Whether a write is taken this cycle: its address and data offered, no response
    /// waiting.
    fn takes_write(&self, i: &Inputs) -> bool {
        self.b.is_none() && i.aw.is_some() && i.w.is_some()
    }

    /// The clock edge.
    pub fn clock(&mut self, i: &Inputs) {
        // A read taken in the cycle of a write returns the register before the write.
        let read = i.ar.map(|addr| match Reg::at(addr) {
            Some(r) => (self.read(r, i), OKAY),
            None => (0, SLVERR),
        });
        let (mut start, mut pending) = (false, self.pending || i.done);
        if let (true, Some(addr), Some((data, strb))) = (self.takes_write(i), i.aw, i.w) {
            let mask = (0..4).filter(|b| strb >> b & 1 != 0).fold(0u32, |m, b| m | 0xff << (8 * b));
            self.b = Some(match Reg::at(addr) {
                Some(r) => {
                    let k = Reg::ALL.iter().position(|x| *x == r).expect("a register");
                    let w = r.writable() & mask;
                    self.values[k] = (self.values[k] & !w) | (data & w);
                    if r == Reg::Control && mask & data & 1 != 0 {
                        start = true;
                    }
                    if r == Reg::Irq && mask & data & 1 != 0 && !i.done {
                        pending = false;
                    }
                    OKAY
                }
                None => SLVERR,
            });
        } else if i.b_ready {
            self.b = None;
        }
        if let (true, Some(r)) = (self.r.is_none(), read) {
            self.r = Some(r);
        } else if i.r_ready {
            self.r = None;
        }
        (self.start, self.pending) = (start, pending);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A host on the bus: each access offered until taken, its answer awaited.
    struct Host {
        regs: GpuRegs,
        /// What `gpu_top` drives.
        status: u32,
        done: bool,
    }

    impl Host {
        fn new() -> Host {
            Host { regs: GpuRegs::new(10), status: 0, done: false }
        }

        fn step(&mut self, i: Inputs) -> Outputs {
            let i = Inputs { status: self.status, done: std::mem::take(&mut self.done), ..i };
            let o = self.regs.outputs(&i);
            self.regs.clock(&i);
            o
        }

        fn write(&mut self, addr: u32, data: u32, strb: u8) -> u8 {
            let offer = Inputs { aw: Some(addr), w: Some((data, strb)), ..Inputs::default() };
            while !self.step(offer).w_ready {}
            loop {
                if let Some(resp) = self.step(Inputs { b_ready: true, ..Inputs::default() }).b {
                    return resp;
                }
            }
        }

        fn read(&mut self, addr: u32) -> (u32, u8) {
            while !self.step(Inputs { ar: Some(addr), ..Inputs::default() }).ar_ready {}
            loop {
                if let Some(r) = self.step(Inputs { r_ready: true, ..Inputs::default() }).r {
                    return r;
                }
            }
        }
    }

    #[test]
    fn registers_read_back_what_was_written_under_the_strobes() {
        let mut h = Host::new();
        assert_eq!(h.read(Reg::Id as u32), (u32::from_be_bytes([b'E', b'P', 2, 10]), OKAY));
        assert_eq!(h.write(Reg::VbAddr as u32, 0x1234_5678, 0xf), OKAY);
        assert_eq!(h.write(Reg::VbAddr as u32, 0xaabb_ccdd, 0b0101), OKAY);
        assert_eq!(h.read(Reg::VbAddr as u32), (0x12bb_56dd, OKAY));
        assert_eq!(h.write(Reg::ColorPitch as u32, 0xffff_ffff, 0xf), OKAY);
        assert_eq!(h.read(Reg::ColorPitch as u32), (0xffff, OKAY));
        // Read-only registers ignore writes; addresses outside the map answer SLVERR.
        assert_eq!(h.write(Reg::Id as u32, 0, 0xf), OKAY);
        assert_eq!(h.read(Reg::Id as u32).0, id(10));
        assert_eq!(h.write(0x30, 1, 0xf), SLVERR);
        assert_eq!(h.read(0x3c), (0, SLVERR));
        h.status = 0x5a5;
        assert_eq!(h.read(Reg::Status as u32), (0x5a5, OKAY));
    }

    #[test]
    fn start_is_one_cycle_and_the_interrupt_is_cleared_by_writing_one() {
        let mut h = Host::new();
        h.write(Reg::Control as u32, 0b111, 0xf);
        assert_eq!(h.read(Reg::Control as u32).0, 0b110, "START reads 0");
        let o = h.step(Inputs::default());
        assert!(!o.start && o.clear && !o.irq);
        // The write's edge raises start for exactly the next cycle.
        let offer = Inputs { aw: Some(Reg::Control as u32), w: Some((0b101, 1)), ..Inputs::default() };
        assert!(h.step(offer).w_ready);
        let o = h.step(Inputs { b_ready: true, ..Inputs::default() });
        assert!(o.start && !o.clear);
        assert!(!h.step(Inputs::default()).start);
        h.done = true;
        h.step(Inputs::default());
        assert!(h.step(Inputs::default()).irq);
        assert_eq!(h.read(Reg::Irq as u32).0, 1);
        h.write(Reg::Irq as u32, 1, 0xf);
        assert!(!h.step(Inputs::default()).irq);
        assert_eq!(h.read(Reg::Irq as u32).0, 0);
    }
}
