//! `texture_path`: a textured fragment's way from `span` to the blending `pixel_out` (paper
//! 001 §II-5: s·q, t·q and q per pixel from the triangle's planes, then the texture unit).
//! Cycle for cycle `model::texture_path::TexturePath`, whose module documentation is the
//! specification; size class 10 (`texture_setup`'s formats).
//!
//! ```text
//!  inp (a fragment) ──> texture_setup, pixel part ──> texture_unit ──> out (BlendPixelSource)
//!  inp_new, tri$*,       3 stages, en                  (64 sets, 2 ways,   x, y, z, mode from the
//!  state$* (a triangle's cf: the lit colour beside     4-word lines)       side RAM; rgb, alpha
//!   first fragment       it in 3 registers                                 from the unit
//!        └─ phase: RUN -> DRAIN -> SETUP -> FIRST -> RUN
//! ```
//!
//! **Phases** (`phase`): RUN takes fragments while the pixel part moves (`en`: its last
//! stage empty or `texture_unit` taking its pixel), unless the fragment offered is a
//! triangle's first (`inp_new`), which sends the path to DRAIN. DRAIN waits for the pixel
//! part to be empty (`in_px`, the pixels in it) and, when the triangle's state (`state$*`,
//! one word) differs from the one loaded (`loaded`), for `texture_unit` to be
//! idle; then, in one cycle, `texture_setup` starts on `tri$*` and `texture_unit` loads the
//! state if it changed (SETUP). SETUP waits for `texture_setup`'s `done` (30 cycles); FIRST
//! takes the waiting fragment when the pixel part moves, and goes back to RUN.
//!
//! **The side RAM.** Each fragment taken writes its x, y, z and blend mode at `wp`; they are
//! read, synchronously at the read pointer's next value as `texture_unit`'s RAMs are, while
//! it is at `texture_unit`'s output. A word is read at least `texture_setup::LATENCY` +
//! `texture_unit::LATENCY` cycles after its write, and at most as many fragments are in
//! flight as the pixel part's stages and `texture_unit::IN_FLIGHT` (3 + 32), so 64 words
//! never overflow. `texture_unit`'s tag is not used (0).
//!
//! Model: `model::texture_path`. Tests: `testbenches/tests/texture_path.rs`. Emitted:
//! `edgepaint emit --unit texture_path --param EXACT=0|1`.

use crate::emit::{emit_unit, Emitted};
use crate::n10::links::{BlendPixelSource, PixelSink};
use crate::n10::widths::{DEPTH, SCREEN};
use crate::texture_cache::{CacheCounters, TexMemory, ADDR};
use crate::texture_setup::{TexTri, TextureSetup};
use crate::texture_unit::{TextureState, TextureUnit6424};
use crate::Params;
use blank::Blank;
use rust_hdl::prelude::*;
use rust_hdl::widgets::prelude::RAM;

/// log2 of the side RAM's words: room for every fragment in flight.
const SB: usize = 6;
const _: () = assert!(crate::texture_setup::LATENCY + crate::texture_unit::IN_FLIGHT < 1 << SB);
/// A side word: x, y, z, the blend mode.
const SIDE: usize = 2 * SCREEN + DEPTH + 3;
/// The state word: the 12 fields of `state` side by side.
pub(crate) const SW: usize = 4 + 4 + 4 + ADDR + 1 + 1 + 2 + 2 + 2 + 3 + 1 + 3;
/// The phases' codes.
const PHASES: [u64; 4] = [0, 1, 2, 3];

/// The texture path: see the module documentation.
#[derive(LogicBlock, Blank)]
pub struct TexturePath {
    pub clock: Signal<In, Clock>,
    /// The fragments: position, depth and lit colour.
    pub inp: PixelSink,
    /// The fragment offered is its triangle's first: `tri` holds the triangle.
    pub inp_new: Signal<In, Bit>,
    /// The triangle (`model::texture_path::TexTriangle`) and its blend mode (`rtl::blend`'s
    /// code), with a first fragment.
    pub tri: TexTri,
    pub tri_mode: Signal<In, Bits<3>>,
    /// The triangle's texture state, with `tri`.
    pub state: TextureState,
    /// A pulse: the texture cache invalidates every line.
    pub inp_flush: Signal<In, Bit>,
    /// The textured fragments: the environment's colour and alpha, the triangle's mode.
    pub out: BlendPixelSource,
    /// `texture_unit`'s memory read port and counters.
    pub mem: TexMemory,
    pub counters: CacheCounters,
    /// No fragment in the path, and no triangle being set up.
    pub idle: Signal<Out, Bit>,

    setup: TextureSetup,
    unit: TextureUnit6424,
    side: RAM<Bits<SIDE>, SB>,
    phase: DFF<Bits<2>>,
    loaded: DFF<Bits<SW>>,
    /// Pixels in texture_setup's pixel part.
    in_px: DFF<Bits<2>>,
    /// The lit colour beside the pixel part's three stages.
    cf: [DFF<Bits<24>>; 3],
    wp: DFF<Bits<SB>>,
    rt: DFF<Bits<SB>>,
    st_word: Signal<Local, Bits<SW>>,
    same: Signal<Local, Bit>,
    start: Signal<Local, Bit>,
    en: Signal<Local, Bit>,
    accept: Signal<Local, Bit>,
    leave: Signal<Local, Bit>,
    side_in: Signal<Local, Bits<SIDE>>,
    /// The phases: RUN, DRAIN, SETUP, FIRST.
    run: Constant<Bits<2>>,
    drain: Constant<Bits<2>>,
    setup_phase: Constant<Bits<2>>,
    first: Constant<Bits<2>>,
    /// Where x, y and z stand in a side word.
    at_x: Constant<Bits<8>>,
    at_y: Constant<Bits<8>>,
    at_z: Constant<Bits<8>>,
}

impl TexturePath {
    /// The path, its level of detail by GL's exact rho when `exact` (else 001's eq. 4).
    pub fn new(exact: bool) -> TexturePath {
        TexturePath {
            unit: TextureUnit6424::new(exact),
            run: Constant::new(PHASES[0].to_bits()),
            drain: Constant::new(PHASES[1].to_bits()),
            setup_phase: Constant::new(PHASES[2].to_bits()),
            first: Constant::new(PHASES[3].to_bits()),
            at_x: Constant::new((SCREEN + DEPTH + 3).to_bits()),
            at_y: Constant::new((DEPTH + 3).to_bits()),
            at_z: Constant::new(3usize.to_bits()),
            ..TexturePath::blank()
        }
    }
}

impl Logic for TexturePath {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, phase, loaded, in_px, wp, rt);
        for k in 0..3 {
            self.cf[k].clock.next = self.clock.val();
            self.cf[k].d.next = self.cf[k].q.val();
        }
        clock!(self, clock, setup, unit);

        // The triangle's state, one word, against the one loaded.
        self.st_word.next = (bit_cast::<SW, 4>(self.state.ws.val()) << 49)
            | (bit_cast::<SW, 4>(self.state.hs.val()) << 45)
            | (bit_cast::<SW, 4>(self.state.levels.val()) << 41)
            | (bit_cast::<SW, ADDR>(self.state.base.val()) << 15)
            | (bit_cast::<SW, 2>(self.state.mip.val()) << 11)
            | (bit_cast::<SW, 2>(self.state.wrap_s.val()) << 9)
            | (bit_cast::<SW, 2>(self.state.wrap_t.val()) << 7)
            | (bit_cast::<SW, 3>(self.state.format.val()) << 4)
            | bit_cast::<SW, 3>(self.state.env.val());
        if self.state.min_linear.val() {
            self.st_word.next = self.st_word.val().replace_bit(14, true);
        }
        if self.state.mag_linear.val() {
            self.st_word.next = self.st_word.val().replace_bit(13, true);
        }
        if self.state.gaussian.val() {
            self.st_word.next = self.st_word.val().replace_bit(3, true);
        }
        self.same.next = self.st_word.val() == self.loaded.q.val();
        self.start.next = (self.phase.q.val() == self.drain.val())
            & (self.in_px.q.val() == 0)
            & (self.same.val() | self.unit.idle.val());

        // texture_setup: the triangle at the start, its pixel part moving with `en`.
        self.setup.start.next = self.start.val();
        TexTri::link(&mut self.tri, &mut self.setup.tri);

        // texture_unit: the pixel part's last stage with the triangle's LOD gradients and
        // the lit colour; the state when it changes.
        self.unit.inp_valid.next = self.setup.out_valid.val();
        self.unit.inp_sq.next = self.setup.out_sq.val();
        self.unit.inp_tq.next = self.setup.out_tq.val();
        self.unit.inp_q.next = self.setup.out_q.val();
        self.unit.inp_dsq_x.next = self.setup.dsq_x.val();
        self.unit.inp_dsq_y.next = self.setup.dsq_y.val();
        self.unit.inp_dtq_x.next = self.setup.dtq_x.val();
        self.unit.inp_dtq_y.next = self.setup.dtq_y.val();
        self.unit.inp_dq_x.next = self.setup.dq_x.val();
        self.unit.inp_dq_y.next = self.setup.dq_y.val();
        self.unit.inp_cf.next = self.cf[2].q.val();
        self.unit.inp_tag.next = 0.into();
        self.unit.st_load.next = self.start.val() & !self.same.val();
        TextureState::link(&mut self.state, &mut self.unit.st);
        self.unit.inp_flush.next = self.inp_flush.val();
        self.unit.out_ready.next = self.out.ready.val();
        TexMemory::link(&mut self.mem, &mut self.unit.mem);
        CacheCounters::link(&mut self.counters, &mut self.unit.counters);

        // Fragments in: the pixel part moves when its last stage is empty or taken.
        self.en.next = !self.setup.out_valid.val() | self.unit.inp_ready.val();
        self.inp.ready.next = self.en.val()
            & (((self.phase.q.val() == self.run.val()) & !self.inp_new.val())
                | (self.phase.q.val() == self.first.val()));
        self.accept.next = self.inp.valid.val() & self.inp.ready.val();
        self.setup.en.next = self.en.val();
        self.setup.inp_valid.next = self.accept.val();
        self.setup.inp_x.next = self.inp.x.val();
        self.setup.inp_y.next = self.inp.y.val();
        if self.en.val() {
            self.cf[0].d.next = (bit_cast::<24, 8>(self.inp.rgb0.val()) << 16)
                | (bit_cast::<24, 8>(self.inp.rgb1.val()) << 8)
                | bit_cast::<24, 8>(self.inp.rgb2.val());
            self.cf[1].d.next = self.cf[0].q.val();
            self.cf[2].d.next = self.cf[1].q.val();
        }
        self.leave.next = self.setup.out_valid.val() & self.unit.inp_ready.val();
        if self.accept.val() & !self.leave.val() {
            self.in_px.d.next = self.in_px.q.val() + 1;
        }
        if !self.accept.val() & self.leave.val() {
            self.in_px.d.next = self.in_px.q.val() - 1;
        }

        // The phases.
        if (self.phase.q.val() == self.run.val()) & self.inp.valid.val() & self.inp_new.val() {
            self.phase.d.next = self.drain.val();
        }
        if self.start.val() {
            self.phase.d.next = self.setup_phase.val();
            self.loaded.d.next = self.st_word.val();
        }
        if (self.phase.q.val() == self.setup_phase.val()) & self.setup.done.val() {
            self.phase.d.next = self.first.val();
        }
        if (self.phase.q.val() == self.first.val()) & self.accept.val() {
            self.phase.d.next = self.run.val();
        }

        // The side RAM: x, y, z and mode at the taking, read at the output.
        self.side_in.next = (bit_cast::<SIDE, SCREEN>(self.inp.x.val()) << self.at_x.val())
            | (bit_cast::<SIDE, SCREEN>(self.inp.y.val()) << self.at_y.val())
            | (bit_cast::<SIDE, DEPTH>(self.inp.z.val()) << self.at_z.val())
            | bit_cast::<SIDE, 3>(self.tri_mode.val());
        self.side.write_clock.next = self.clock.val();
        self.side.read_clock.next = self.clock.val();
        self.side.write_enable.next = self.accept.val();
        self.side.write_address.next = self.wp.q.val();
        self.side.write_data.next = self.side_in.val();
        if self.accept.val() {
            self.wp.d.next = self.wp.q.val() + 1;
        }
        self.side.read_address.next = self.rt.q.val();
        if self.unit.out_valid.val() & self.out.ready.val() {
            self.rt.d.next = self.rt.q.val() + 1;
            self.side.read_address.next = self.rt.q.val() + 1;
        }

        // Out: the unit's colour and alpha, the side word's position, depth and mode.
        self.out.valid.next = self.unit.out_valid.val();
        self.out.x.next = self.side.read_data.val().get_bits::<SCREEN>(self.at_x.val().index());
        self.out.y.next = self.side.read_data.val().get_bits::<SCREEN>(self.at_y.val().index());
        self.out.z.next = self.side.read_data.val().get_bits::<DEPTH>(self.at_z.val().index());
        self.out.mode.next = self.side.read_data.val().get_bits::<3>(0);
        self.out.rgb0.next = self.unit.out_rgba.val().get_bits::<8>(24);
        self.out.rgb1.next = self.unit.out_rgba.val().get_bits::<8>(16);
        self.out.rgb2.next = self.unit.out_rgba.val().get_bits::<8>(8);
        self.out.alpha.next = self.unit.out_rgba.val().get_bits::<8>(0);
        self.idle.next = self.unit.idle.val() & (self.in_px.q.val() == 0) & (self.phase.q.val() == self.run.val());
    }
}

crate::pins!(TexturePath {
    clock: clock,
    inputs: [inp_new, tri_mode, inp_flush],
    outputs: [idle],
    links: [inp, tri, state, out, mem, counters],
});

/// `UNITS` entry: the path, the level-of-detail rule `params["EXACT"]`.
pub fn emit_texture_path(params: &Params) -> Result<Emitted, String> {
    let exact = crate::exact_rule("texture_path", params)?;
    Ok(emit_unit("texture_path", TexturePath::new(exact), params))
}
