//! The triangle queue between `command_parser` and `cull_sort` in `gpu_top`
//! (`model::triangle_queue`, cycle for cycle): `2^AB` triangles in block RAM, so that the
//! parser runs ahead while the rasterizer draws large triangles and the queue feeds it
//! while it culls runs of small ones in a cycle or two each (001's command parser hands
//! triangles over as the rasterizer asks, Fig. 4's CP Ready; a mesh's culled triangles
//! come in runs, faster than the parser reads them).
//!
//! A vertex is one word of [`VW`] bits (x, y, z, R, G, B, 1/w from bit 0 up), each of the
//! three vertices a RAM of its own. Reads are synchronous: the read address is the entry
//! that will be at the head next cycle (the head, or the one after it when the head is
//! taken), and an entry is at the head from the second cycle after it was written (its
//! write and a read of it never share a clock edge). `inp.ready` is a registered "not
//! full"; `idle` is "empty".
//!
//! Emitted: `hdl-out/triangle_queue.v`.

use super::cull_sort::{COLOR, INV_W, XY, Z};
use super::links::{TriangleSink, TriangleSource};
use crate::emit::{emit_unit, Emitted};
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::RAM;

/// A vertex's word: x, y, z, R, G, B and 1/w, from bit 0 up.
pub const VW: usize = 2 * XY + Z + 3 * COLOR + INV_W;

/// The queue sizes the RTL is built for (`DEPTH`).
pub const DEPTHS: [u32; 4] = [4, 64, 256, 512];

/// `2^AB` triangles: see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct TriangleQueue<const AB: usize> {
    pub clock: Signal<In, Clock>,
    pub inp: TriangleSink,
    pub out: TriangleSource,
    /// Nothing queued.
    pub idle: Signal<Out, Bit>,
    v0_ram: RAM<Bits<VW>, AB>,
    v1_ram: RAM<Bits<VW>, AB>,
    v2_ram: RAM<Bits<VW>, AB>,
    /// The entries written next and at the head; the triangles queued; one written last
    /// cycle (not yet readable).
    wr: DFF<Bits<AB>>,
    rd: DFF<Bits<AB>>,
    level: DFF<Bits<16>>,
    fresh: DFF<Bit>,
    depth: Constant<Bits<16>>,
    push: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    /// The entry at the head next cycle.
    read_at: Signal<Local, Bits<AB>>,
    at_y: Constant<Bits<16>>,
    at_z: Constant<Bits<16>>,
    at_c0: Constant<Bits<16>>,
    at_c1: Constant<Bits<16>>,
    at_c2: Constant<Bits<16>>,
    at_iw: Constant<Bits<16>>,
}

impl<const AB: usize> Default for TriangleQueue<AB> {
    fn default() -> Self {
        assert!((2..=9).contains(&AB), "TriangleQueue<{AB}>: 4 to 512 entries");
        let at = |n: usize| Constant::new(bits(n as u64));
        TriangleQueue {
            depth: at(1 << AB),
            at_y: at(XY),
            at_z: at(2 * XY),
            at_c0: at(2 * XY + Z),
            at_c1: at(2 * XY + Z + COLOR),
            at_c2: at(2 * XY + Z + 2 * COLOR),
            at_iw: at(2 * XY + Z + 3 * COLOR),
            ..TriangleQueue::blank()
        }
    }
}

impl<const AB: usize> Logic for TriangleQueue<AB> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, wr, rd, level, fresh);
        self.v0_ram.read_clock.next = self.clock.val();
        self.v0_ram.write_clock.next = self.clock.val();
        self.v1_ram.read_clock.next = self.clock.val();
        self.v1_ram.write_clock.next = self.clock.val();
        self.v2_ram.read_clock.next = self.clock.val();
        self.v2_ram.write_clock.next = self.clock.val();

        // The handshakes: room is the registered level's, the head is an entry written two
        // cycles ago or earlier.
        self.inp.ready.next = self.level.q.val() < self.depth.val();
        self.out.valid.next = self.level.q.val().any() & !(self.fresh.q.val() & (self.level.q.val() == 1));
        self.idle.next = !self.level.q.val().any();
        self.push.next = self.inp.valid.val() & self.inp.ready.val();
        self.pop.next = self.out.valid.val() & self.out.ready.val();
        self.fresh.d.next = self.push.val();
        if self.push.val() {
            self.wr.d.next = self.wr.q.val() + 1;
        }
        if self.pop.val() {
            self.rd.d.next = self.rd.q.val() + 1;
        }
        if self.push.val() & !self.pop.val() {
            self.level.d.next = self.level.q.val() + 1;
        }
        if !self.push.val() & self.pop.val() {
            self.level.d.next = self.level.q.val() - 1;
        }

        // Writes: the triangle in, a word a vertex.
        self.v0_ram.write_enable.next = self.push.val();
        self.v1_ram.write_enable.next = self.push.val();
        self.v2_ram.write_enable.next = self.push.val();
        self.v0_ram.write_address.next = self.wr.q.val();
        self.v1_ram.write_address.next = self.wr.q.val();
        self.v2_ram.write_address.next = self.wr.q.val();
        self.v0_ram.write_data.next = bit_cast::<VW, XY>(self.inp.v0_x.val())
            | (bit_cast::<VW, XY>(self.inp.v0_y.val()) << self.at_y.val())
            | (bit_cast::<VW, Z>(self.inp.v0_z.val()) << self.at_z.val())
            | (bit_cast::<VW, COLOR>(self.inp.v0_c0.val()) << self.at_c0.val())
            | (bit_cast::<VW, COLOR>(self.inp.v0_c1.val()) << self.at_c1.val())
            | (bit_cast::<VW, COLOR>(self.inp.v0_c2.val()) << self.at_c2.val())
            | (bit_cast::<VW, INV_W>(self.inp.v0_iw.val()) << self.at_iw.val());
        self.v1_ram.write_data.next = bit_cast::<VW, XY>(self.inp.v1_x.val())
            | (bit_cast::<VW, XY>(self.inp.v1_y.val()) << self.at_y.val())
            | (bit_cast::<VW, Z>(self.inp.v1_z.val()) << self.at_z.val())
            | (bit_cast::<VW, COLOR>(self.inp.v1_c0.val()) << self.at_c0.val())
            | (bit_cast::<VW, COLOR>(self.inp.v1_c1.val()) << self.at_c1.val())
            | (bit_cast::<VW, COLOR>(self.inp.v1_c2.val()) << self.at_c2.val())
            | (bit_cast::<VW, INV_W>(self.inp.v1_iw.val()) << self.at_iw.val());
        self.v2_ram.write_data.next = bit_cast::<VW, XY>(self.inp.v2_x.val())
            | (bit_cast::<VW, XY>(self.inp.v2_y.val()) << self.at_y.val())
            | (bit_cast::<VW, Z>(self.inp.v2_z.val()) << self.at_z.val())
            | (bit_cast::<VW, COLOR>(self.inp.v2_c0.val()) << self.at_c0.val())
            | (bit_cast::<VW, COLOR>(self.inp.v2_c1.val()) << self.at_c1.val())
            | (bit_cast::<VW, COLOR>(self.inp.v2_c2.val()) << self.at_c2.val())
            | (bit_cast::<VW, INV_W>(self.inp.v2_iw.val()) << self.at_iw.val());

        // Reads: the entry at the head next cycle.
        self.read_at.next = self.rd.q.val();
        if self.pop.val() {
            self.read_at.next = self.rd.q.val() + 1;
        }
        self.v0_ram.read_address.next = self.read_at.val();
        self.v1_ram.read_address.next = self.read_at.val();
        self.v2_ram.read_address.next = self.read_at.val();
        self.out.v0_x.next = self.v0_ram.read_data.val().get_bits::<XY>(0);
        self.out.v0_y.next = self.v0_ram.read_data.val().get_bits::<XY>(self.at_y.val().index());
        self.out.v0_z.next = self.v0_ram.read_data.val().get_bits::<Z>(self.at_z.val().index());
        self.out.v0_c0.next = self.v0_ram.read_data.val().get_bits::<COLOR>(self.at_c0.val().index());
        self.out.v0_c1.next = self.v0_ram.read_data.val().get_bits::<COLOR>(self.at_c1.val().index());
        self.out.v0_c2.next = self.v0_ram.read_data.val().get_bits::<COLOR>(self.at_c2.val().index());
        self.out.v0_iw.next = self.v0_ram.read_data.val().get_bits::<INV_W>(self.at_iw.val().index());
        self.out.v1_x.next = self.v1_ram.read_data.val().get_bits::<XY>(0);
        self.out.v1_y.next = self.v1_ram.read_data.val().get_bits::<XY>(self.at_y.val().index());
        self.out.v1_z.next = self.v1_ram.read_data.val().get_bits::<Z>(self.at_z.val().index());
        self.out.v1_c0.next = self.v1_ram.read_data.val().get_bits::<COLOR>(self.at_c0.val().index());
        self.out.v1_c1.next = self.v1_ram.read_data.val().get_bits::<COLOR>(self.at_c1.val().index());
        self.out.v1_c2.next = self.v1_ram.read_data.val().get_bits::<COLOR>(self.at_c2.val().index());
        self.out.v1_iw.next = self.v1_ram.read_data.val().get_bits::<INV_W>(self.at_iw.val().index());
        self.out.v2_x.next = self.v2_ram.read_data.val().get_bits::<XY>(0);
        self.out.v2_y.next = self.v2_ram.read_data.val().get_bits::<XY>(self.at_y.val().index());
        self.out.v2_z.next = self.v2_ram.read_data.val().get_bits::<Z>(self.at_z.val().index());
        self.out.v2_c0.next = self.v2_ram.read_data.val().get_bits::<COLOR>(self.at_c0.val().index());
        self.out.v2_c1.next = self.v2_ram.read_data.val().get_bits::<COLOR>(self.at_c1.val().index());
        self.out.v2_c2.next = self.v2_ram.read_data.val().get_bits::<COLOR>(self.at_c2.val().index());
        self.out.v2_iw.next = self.v2_ram.read_data.val().get_bits::<INV_W>(self.at_iw.val().index());
    }
}

crate::pins!(impl[const AB: usize] TriangleQueue<AB> {
    clock: clock,
    inputs: [],
    outputs: [idle],
    links: [inp, out],
});

/// `UNITS` entry: the queue with `params["DEPTH"]` entries.
pub fn emit_triangle_queue(params: &Params) -> Result<Emitted, String> {
    let unit = "triangle_queue";
    Ok(match params["DEPTH"] {
        4 => emit_unit(unit, TriangleQueue::<2>::default(), params),
        64 => emit_unit(unit, TriangleQueue::<6>::default(), params),
        256 => emit_unit(unit, TriangleQueue::<8>::default(), params),
        512 => emit_unit(unit, TriangleQueue::<9>::default(), params),
        d => return Err(format!("a triangle queue of {d} entries: {DEPTHS:?}")),
    })
}
