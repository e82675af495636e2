//! `gpu_regs`: the register block a host drives `gpu_top` through, an AXI4-Lite slave
//! (the bundle `links::LiteSlave`, ports `host$*`). The map, the bus's timing and the
//! registers' behaviour are `model::gpu_regs`'s, which this unit follows on every cycle.
//!
//! Emitted: `hdl-out/gpu_regs.v`.

use super::links::LiteSlave;
use super::widths::CLASS;
use crate::emit::{emit_unit, Emitted};
use crate::Params;
use rust_hdl::prelude::*;

/// `model::gpu_regs::id` of this build, as a signal.
#[derive(LogicBlock)]
pub struct IdWord {
    pub id: Signal<Out, Bits<32>>,
    value: Constant<Bits<32>>,
}

impl Default for IdWord {
    fn default() -> Self {
        IdWord { id: Default::default(), value: Constant::new(bits(model::gpu_regs::id(CLASS).into())) }
    }
}

impl Logic for IdWord {
    #[hdl_gen]
    fn update(&mut self) {
        self.id.next = self.value.val();
    }
}

/// The register block: see the module documentation and `model::gpu_regs::Reg` (word
/// index = byte address / 4).
#[derive(LogicBlock, Default)]
pub struct GpuRegs {
    pub clock: Signal<In, Clock>,
    pub host: LiteSlave,
    /// From `gpu_top`: `STATUS`, `FRAME_CYCLES`, `TRIANGLES`, and a frame's end.
    pub status: Signal<In, Bits<32>>,
    pub frame_cycles: Signal<In, Bits<32>>,
    pub triangles: Signal<In, Bits<32>>,
    pub done: Signal<In, Bit>,
    /// To `gpu_top`: a frame's start (one cycle), `CONTROL`'s CLEAR, the interrupt, and the
    /// buffers' addresses.
    pub start: Signal<Out, Bit>,
    pub clear: Signal<Out, Bit>,
    pub irq: Signal<Out, Bit>,
    pub vb_addr: Signal<Out, Bits<32>>,
    pub color_base: Signal<Out, Bits<32>>,
    pub color_pitch: Signal<Out, Bits<16>>,
    pub depth_base: Signal<Out, Bits<32>>,
    pub depth_pitch: Signal<Out, Bits<16>>,
    /// `SCREEN`: the buffers' width (bits 0-15) and height (16-31) in pixels.
    pub screen: Signal<Out, Bits<32>>,
    /// `CONTROL`'s CLEAR (bit 1) and IRQ_EN (bit 2); bit 0 stays 0.
    control: DFF<Bits<3>>,
    vb: DFF<Bits<32>>,
    cbase: DFF<Bits<32>>,
    cpitch: DFF<Bits<16>>,
    zbase: DFF<Bits<32>>,
    zpitch: DFF<Bits<16>>,
    screen_r: DFF<Bits<32>>,
    start_r: DFF<Bit>,
    pending: DFF<Bit>,
    b_valid: DFF<Bit>,
    b_resp: DFF<Bits<2>>,
    r_valid: DFF<Bit>,
    r_data: DFF<Bits<32>>,
    r_resp: DFF<Bits<2>>,
    ident: IdWord,
    /// The write taken this cycle: its word index, its strobes as a bit mask, and each
    /// register merged with it.
    write: Signal<Local, Bit>,
    wi: Signal<Local, Bits<4>>,
    mask: Signal<Local, Bits<32>>,
    merged: Signal<Local, Bits<32>>,
    ri: Signal<Local, Bits<4>>,
}

impl Logic for GpuRegs {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, control, vb, cbase, cpitch, zbase, zpitch, screen_r, start_r, pending, b_valid, b_resp,
            r_valid, r_data, r_resp
        );
        self.start.next = self.start_r.q.val();
        self.clear.next = self.control.q.val().get_bit(1);
        self.irq.next = self.control.q.val().get_bit(2) & self.pending.q.val();
        self.vb_addr.next = self.vb.q.val();
        self.color_base.next = self.cbase.q.val();
        self.color_pitch.next = self.cpitch.q.val();
        self.depth_base.next = self.zbase.q.val();
        self.depth_pitch.next = self.zpitch.q.val();
        self.screen.next = self.screen_r.q.val();
        self.host.b_valid.next = self.b_valid.q.val();
        self.host.b_resp.next = self.b_resp.q.val();
        self.host.r_valid.next = self.r_valid.q.val();
        self.host.r_data.next = self.r_data.q.val();
        self.host.r_resp.next = self.r_resp.q.val();
        self.host.ar_ready.next = !self.r_valid.q.val();

        // A write: address and data offered together, no response waiting.
        self.write.next = !self.b_valid.q.val() & self.host.aw_valid.val() & self.host.w_valid.val();
        self.host.aw_ready.next = self.write.val();
        self.host.w_ready.next = self.write.val();
        self.wi.next = self.host.aw_addr.val().get_bits::<4>(2);
        self.merged.next = 0.into();
        self.mask.next = 0.into();
        for b in 0..4 {
            for k in 0..8 {
                self.mask.next = self.mask.val().replace_bit(8 * b + k, self.host.w_strb.val().get_bit(b));
            }
        }
        self.start_r.d.next = false;
        self.pending.d.next = self.pending.q.val() | self.done.val();
        if self.b_valid.q.val() & self.host.b_ready.val() {
            self.b_valid.d.next = false;
        }
        if self.write.val() {
            self.b_valid.d.next = true;
            self.b_resp.d.next = 0.into();
            if self.wi.val() > 11 {
                self.b_resp.d.next = 2.into();
            }
            if self.wi.val() == 1 {
                self.merged.next = (bit_cast::<32, 3>(self.control.q.val()) & !self.mask.val())
                    | (self.host.w_data.val() & self.mask.val());
                self.control.d.next = self.merged.val().get_bits::<3>(0).replace_bit(0, false);
                self.start_r.d.next = self.merged.val().get_bit(0);
            }
            if (self.wi.val() == 3) & self.mask.val().get_bit(0) & self.host.w_data.val().get_bit(0) & !self.done.val()
            {
                self.pending.d.next = false;
            }
            if self.wi.val() == 4 {
                self.vb.d.next = (self.vb.q.val() & !self.mask.val()) | (self.host.w_data.val() & self.mask.val());
            }
            if self.wi.val() == 5 {
                self.cbase.d.next =
                    (self.cbase.q.val() & !self.mask.val()) | (self.host.w_data.val() & self.mask.val());
            }
            if self.wi.val() == 6 {
                self.merged.next = (bit_cast::<32, 16>(self.cpitch.q.val()) & !self.mask.val())
                    | (self.host.w_data.val() & self.mask.val());
                self.cpitch.d.next = self.merged.val().get_bits::<16>(0);
            }
            if self.wi.val() == 7 {
                self.zbase.d.next =
                    (self.zbase.q.val() & !self.mask.val()) | (self.host.w_data.val() & self.mask.val());
            }
            if self.wi.val() == 8 {
                self.merged.next = (bit_cast::<32, 16>(self.zpitch.q.val()) & !self.mask.val())
                    | (self.host.w_data.val() & self.mask.val());
                self.zpitch.d.next = self.merged.val().get_bits::<16>(0);
            }
            if self.wi.val() == 11 {
                self.screen_r.d.next =
                    (self.screen_r.q.val() & !self.mask.val()) | (self.host.w_data.val() & self.mask.val());
            }
        }

        // A read: taken when no read data wait; the data the next cycle.
        self.ri.next = self.host.ar_addr.val().get_bits::<4>(2);
        if self.r_valid.q.val() & self.host.r_ready.val() {
            self.r_valid.d.next = false;
        }
        if !self.r_valid.q.val() & self.host.ar_valid.val() {
            self.r_valid.d.next = true;
            self.r_resp.d.next = 0.into();
            self.r_data.d.next = 0.into();
            if self.ri.val() == 0 {
                self.r_data.d.next = self.ident.id.val();
            }
            if self.ri.val() == 1 {
                self.r_data.d.next = bit_cast::<32, 3>(self.control.q.val());
            }
            if self.ri.val() == 2 {
                self.r_data.d.next = self.status.val();
            }
            if (self.ri.val() == 3) & self.pending.q.val() {
                self.r_data.d.next = 1.into();
            }
            if self.ri.val() == 4 {
                self.r_data.d.next = self.vb.q.val();
            }
            if self.ri.val() == 5 {
                self.r_data.d.next = self.cbase.q.val();
            }
            if self.ri.val() == 6 {
                self.r_data.d.next = bit_cast::<32, 16>(self.cpitch.q.val());
            }
            if self.ri.val() == 7 {
                self.r_data.d.next = self.zbase.q.val();
            }
            if self.ri.val() == 8 {
                self.r_data.d.next = bit_cast::<32, 16>(self.zpitch.q.val());
            }
            if self.ri.val() == 9 {
                self.r_data.d.next = self.frame_cycles.val();
            }
            if self.ri.val() == 10 {
                self.r_data.d.next = self.triangles.val();
            }
            if self.ri.val() == 11 {
                self.r_data.d.next = self.screen_r.q.val();
            }
            if self.ri.val() > 11 {
                self.r_resp.d.next = 2.into();
            }
        }
    }
}

crate::pins!(GpuRegs {
    clock: clock,
    inputs: [status, frame_cycles, triangles, done],
    outputs: [start, clear, irq, vb_addr, color_base, color_pitch, depth_base, depth_pitch, screen],
    links: [host],
});

/// `UNITS` entry: the register block of this build.
pub fn emit_gpu_regs(params: &Params) -> Result<Emitted, String> {
    Ok(emit_unit("gpu_regs", GpuRegs::default(), params))
}
