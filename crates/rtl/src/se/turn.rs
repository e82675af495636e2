//! Corner-turning memories: the old-z, new-z and R, G, B blocks of the shading engine
//! (000 Fig. 6) held in small RAMs instead of P shift registers each.
//!
//! The interpolator and the z compare (Figs. 8-10) work on one bit of every pixel per clock
//! (a *bit plane*, P bits); the memory ports on whole words of one port group, pixels
//! 4j .. 4j + 3 (000's 4-way interleaving). A W-bit word block of P pixels is W memories of
//! Q = P/4 entries of 4 bits, stored skewed:
//!
//! ```text
//! memory m, entry j  =  bit (m - j) mod W of pixels 4j .. 4j+3 (entry bit k: pixel 4j+k)
//! ```
//!
//! so that bit plane b meets each memory once (entry (m - b) mod W of memory m, for the Q
//! entries that exist) and port group j meets each memory once (entry j of every memory).
//! Either way every memory is written or read once per clock: one write port and one
//! asynchronous read port, which Yosys maps to LUT RAM (ECP5 `TRELLIS_DPR16X4`, 16 x 4) and
//! an ASIC flow to a register file. Between the memories and the ports sits a barrel
//! rotator (log2 of the rotation range stages of 2:1 multiplexers) undoing the skew.
//! Needs Q <= W, so that a plane's Q groups fall in distinct memories.
//!
//! * [`PlanesToWords`] (new z, R, G, B): a bit plane in per clock, a port group's 4 words
//!   out, read in the same clock. The plane is registered first and written at the next
//!   edge (so the write rotator and the memories' write port do not add to the path that
//!   produces the plane): it can be read two edges after it is offered.
//! * [`WordsToPlanes`] (old z): a port group's 4 words in per clock, a bit plane out.
//!
//! Like [`crate::mul::Mul`], each block writes its own Verilog and computes the same in
//! Rust for rust-hdl's simulator; the SE's dual-simulator tests guard that the two agree.

use blank::Blank;
use rust_hdl::prelude::*;

/// Entry of memory `m` that bit `b` of a plane goes to (or comes from): (m - b) mod W, as
/// the Verilog computes it in 8 bits.
fn skewed(m: usize, b: usize, w: usize) -> usize {
    (if m >= b { m - b } else { (m + w).wrapping_sub(b) }) & 255
}

/// The rotation (mod W) a rotator over `w` slots makes for select value `b`: the low
/// stages(w) bits of `b` (the rest of the 8-bit `plane` is not wired to it).
fn reach(b: usize, w: usize) -> usize {
    (b & ((1 << stages(w)) - 1)) % w
}

/// Stages of a rotator over `range` positions: ceil(log2 range).
fn stages(range: usize) -> usize {
    range.next_power_of_two().trailing_zeros() as usize
}

/// The Verilog of a barrel rotator over `w` slots of 4 bits: `out` = `inp` rotated by
/// `by` (`n` select bits) slots, right (slot s of `out` = slot s + by of `inp`) or left.
fn rotator(name: &str, inp: &str, by: &str, n: usize, w: usize, right: bool) -> String {
    let mut v = format!("wire [{}:0] {name}_st;\nassign {name}_st[{}:0] = {inp};\n", 4 * w * (n + 1) - 1, 4 * w - 1);
    for i in 0..n {
        // By c = 2^i slots (c < w: the rotations reach at most w - 1).
        let c = 1 << i;
        let (lo, hi) = (4 * w * i, 4 * w * (i + 1));
        let cut = if right { 4 * c } else { 4 * (w - c) };
        v += &format!(
            "assign {name}_st[{}:{hi}] = {by}[{i}] ? {{{name}_st[{}:{lo}], {name}_st[{}:{}]}} : {name}_st[{}:{lo}];\n",
            hi + 4 * w - 1,
            lo + cut - 1,
            hi - 1,
            lo + cut,
            hi - 1,
        );
    }
    v + &format!("wire [{}:0] {name} = {name}_st[{}:{}];\n", 4 * w - 1, 4 * w * (n + 1) - 1, 4 * w * n)
}

/// The memories' Verilog: W generate blocks `mem_m`, entries of 4 bits, each with `j`, its
/// entry for bit plane `sel` ((m - sel) mod W, `jw` bits); written at `wa` with slot m of
/// `wdata` when `wen`, read asynchronously into slot m of `rd`: at port group `g`, or with
/// `by_plane` at `ra`, which is `j` registered (the entry for the plane offered at the last
/// edge).
fn memories(w: usize, q: usize, sel: &str, jw: usize, (wa, wen): (&str, &str), by_plane: bool) -> String {
    let ra = if by_plane { "ra" } else { "g" };
    format!(
        "wire [{rd}:0] rd;\n\
         genvar m;\n\
         generate\n\
         for (m = 0; m < {w}; m = m + 1) begin : mem_m\n\
         \x20   reg [3:0] mem [0:{qm}];\n\
         \x20   wire [{jm}:0] j = (m >= {sel}) ? m - {sel} : m + {w} - {sel};\n\
         \x20   always @(posedge clock) if ({wen}) mem[{wa}] <= wdata[4*m+3:4*m];\n\
         {reg}\
         \x20   assign rd[4*m+3:4*m] = mem[{ra}];\n\
         end\n\
         endgenerate\n",
        rd = 4 * w - 1,
        qm = q - 1,
        jm = jw - 1,
        reg = if by_plane {
            format!("    reg [{jm}:0] ra;\n    initial ra = m;\n    always @(posedge clock) ra <= j;\n", jm = jw - 1)
        } else {
            String::new()
        },
    )
}

/// Bit planes in, port groups' words out (the new-z and R, G, B blocks): `W`-bit words of
/// `P` pixels. Requires P/4 <= W, P/4 a power of two, W < 64.
#[derive(LogicBlock, Blank)]
pub struct PlanesToWords<const W: usize, const P: usize> {
    pub clock: Signal<In, Clock>,
    /// Write bit plane `plane` (0 = LSB) from `px` (bit x: pixel x): registered at this
    /// clock's edge, in the memories at the next.
    pub we: Signal<In, Bit>,
    pub plane: Signal<In, Bits<8>>,
    pub px: Signal<In, Bits<P>>,
    /// Port group j (its low log2(P/4) bits) shown on `w0` .. `w3`: pixels 4j .. 4j+3.
    pub group: Signal<In, Bits<4>>,
    pub w0: Signal<Out, Bits<W>>,
    pub w1: Signal<Out, Bits<W>>,
    pub w2: Signal<Out, Bits<W>>,
    pub w3: Signal<Out, Bits<W>>,
    /// Entry j of memory m at `_mem[m * P/4 + j]`.
    _mem: Vec<u8>,
    /// The registered write (plane, pixels), if `we` was high at the last edge.
    _wr: Option<(usize, u128)>,
}

impl<const W: usize, const P: usize> Default for PlanesToWords<W, P> {
    fn default() -> Self {
        check(W, P);
        PlanesToWords { _mem: vec![0; W * P / 4], _wr: None, ..PlanesToWords::blank() }
    }
}

/// Panics unless `W`, `P` fit the skewed layout and the ports' widths.
fn check(w: usize, p: usize) {
    let q = p / 4;
    assert!(q.is_power_of_two() && q <= 16 && q <= w && w < 64, "corner turn: P = {p}, W = {w} (need P/4 <= W < 64)");
}

impl<const W: usize, const P: usize> PlanesToWords<W, P> {
    /// Bit plane `b` of pixels `px` into the memories.
    fn write(&mut self, b: usize, px: u128) {
        let q = P / 4;
        // The write rotator turns the plane by `plane`'s low stages(W) bits.
        let r = reach(b, W);
        for m in 0..W {
            let (j, slot) = (skewed(m, b, W), (m + W - r) % W);
            if j < q {
                self._mem[m * q + j] = if slot < q { (px >> (4 * slot) & 15) as u8 } else { 0 };
            }
        }
    }

    /// The words of port group `group`, from the memories as they stand.
    fn read(&mut self) {
        let q = P / 4;
        // Slot b of the rotated read data: memory (b + g) mod W, entry g.
        let g = self.group.val().index() & (q - 1);
        let word = |k: usize| (0..W).fold(0u128, |v, b| v | ((self._mem[(b + g) % W * q + g] >> k & 1) as u128) << b);
        self.w0.next = word(0).to_bits();
        self.w1.next = word(1).to_bits();
        self.w2.next = word(2).to_bits();
        self.w3.next = word(3).to_bits();
    }
}

impl<const W: usize, const P: usize> Logic for PlanesToWords<W, P> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let offered = self.we.val().then(|| (self.plane.val().index(), self.px.val().to_u128()));
            // The plane registered at the last edge goes into the memories at this one.
            if let Some((b, px)) = std::mem::replace(&mut self._wr, offered) {
                self.write(b, px);
            }
        }
        self.read();
    }

    fn connect(&mut self) {
        self.w0.connect();
        self.w1.connect();
        self.w2.connect();
        self.w3.connect();
    }

    fn hdl(&self) -> Verilog {
        let q = P / 4;
        let gb = stages(q).max(1);
        let mut v = format!(
            "// Corner turn, bit planes in, words out (rtl::se::turn): {W} memories of {q} x 4 bits;\n\
             // memory m, entry j holds bit (m - j) mod {W} of pixels 4j .. 4j+3.\n\
             wire [{}:0] g = group[{}:0];\n\
             // The offered plane, registered: written into the memories at the next edge.\n\
             reg we_d;\n\
             reg [7:0] plane_d;\n\
             reg [{}:0] px_d;\n\
             initial we_d = 1'b0;\n\
             always @(posedge clock) begin\n\
             \x20   we_d <= we;\n\
             \x20   plane_d <= plane;\n\
             \x20   px_d <= px;\n\
             end\n\
             // Bit plane `plane_d`: group j goes to memory (j + plane_d) mod {W}, entry j.\n\
             wire [{}:0] planes;\n",
            gb - 1,
            gb - 1,
            P - 1,
            4 * W - 1,
        );
        v += &format!("assign planes[{}:0] = px_d;\n", P - 1);
        if W > q {
            v += &format!("assign planes[{}:{P}] = {}'d0;\n", 4 * W - 1, 4 * (W - q));
        }
        v += &rotator("wdata", "planes", "plane_d", stages(W), W, false);
        v += &memories(W, q, "plane_d", 8, (&format!("j[{}:0]", gb - 1), &format!("we_d && j < {q}")), false);
        v += &rotator("words", "rd", "g", stages(q), W, true);
        v += "integer b;\nalways @(*) begin\n";
        for k in 0..4 {
            v += &format!("    for (b = 0; b < {W}; b = b + 1) w{k}[b] = words[4*b+{k}];\n");
        }
        Verilog::Custom(v + "end\n")
    }
}

/// Port groups' words in, bit planes out (the old-z block): `W`-bit words of `P` pixels.
/// Requires P/4 <= W, P/4 a power of two, W < 64.
#[derive(LogicBlock, Blank)]
pub struct WordsToPlanes<const W: usize, const P: usize> {
    pub clock: Signal<In, Clock>,
    /// Write port group `group` (pixels 4j .. 4j+3) from `d0` .. `d3` at this clock's edge.
    pub we: Signal<In, Bit>,
    pub group: Signal<In, Bits<4>>,
    pub d0: Signal<In, Bits<W>>,
    pub d1: Signal<In, Bits<W>>,
    pub d2: Signal<In, Bits<W>>,
    pub d3: Signal<In, Bits<W>>,
    /// Bit plane `plane` (0 = LSB) shown on `px` (bit x: pixel x) from the next edge on:
    /// the memories' read addresses are registered, so that they and the rotator's select
    /// do not add to the path from the plane's counter.
    pub plane: Signal<In, Bits<8>>,
    pub px: Signal<Out, Bits<P>>,
    /// Entry j of memory m at `_mem[m * P/4 + j]`.
    _mem: Vec<u8>,
    /// The plane shown, `plane` at the last edge.
    _shown: usize,
}

impl<const W: usize, const P: usize> Default for WordsToPlanes<W, P> {
    fn default() -> Self {
        check(W, P);
        WordsToPlanes { _mem: vec![0; W * P / 4], _shown: 0, ..WordsToPlanes::blank() }
    }
}

impl<const W: usize, const P: usize> Logic for WordsToPlanes<W, P> {
    fn update(&mut self) {
        let q = P / 4;
        if self.clock.pos_edge() {
            self._shown = self.plane.val().index();
        }
        if self.clock.pos_edge() && self.we.val() {
            let g = self.group.val().index() & (q - 1);
            let d = [self.d0.val(), self.d1.val(), self.d2.val(), self.d3.val()].map(|w| w.to_u128());
            for m in 0..W {
                // Memory m, entry g: bit (m - g) mod W of the 4 words.
                let b = (m + W - g) % W;
                self._mem[m * q + g] = (0..4).fold(0, |e, k| e | ((d[k] >> b & 1) as u8) << k);
            }
        }
        // Memory m is read at entry (m - plane) mod W; group j of the plane is
        // slot (j + plane) mod W of the read data.
        let b = self._shown;
        let rd: Vec<u8> = (0..W).map(|m| self._mem[m * q + (skewed(m, b, W) & (q - 1))]).collect();
        let r = reach(b, W);
        let px = (0..q).fold(0u128, |v, j| v | (rd[(j + r) % W] as u128) << (4 * j));
        self.px.next = px.to_bits();
    }

    fn connect(&mut self) {
        self.px.connect();
    }

    fn hdl(&self) -> Verilog {
        let q = P / 4;
        let gb = stages(q).max(1);
        let mut v = format!(
            "// Corner turn, words in, bit planes out (rtl::se::turn): {W} memories of {q} x 4 bits;\n\
             // memory m, entry j holds bit (m - j) mod {W} of pixels 4j .. 4j+3.\n\
             wire [{}:0] g = group[{}:0];\n\
             // Group g's words, slot b = bit b of the 4 words, rotated left by g slots.\n\
             reg [{}:0] slots;\n\
             integer b;\n\
             always @(*) for (b = 0; b < {W}; b = b + 1) slots[4*b+:4] = {{d3[b], d2[b], d1[b], d0[b]}};\n",
            gb - 1,
            gb - 1,
            4 * W - 1,
        );
        v += &rotator("wdata", "slots", "g", stages(q), W, false);
        // The rotator reads the low stages(W) bits of the plane shown.
        v += &format!(
            "// The plane shown and the memories' read addresses (`ra` in each), registered.\n\
             reg [{sm}:0] shown;\n\
             initial shown = 0;\n\
             always @(posedge clock) shown <= plane[{sm}:0];\n",
            sm = stages(W) - 1
        );
        v += &memories(W, q, "plane", gb, ("g", "we"), true);
        v += &rotator("turned", "rd", "shown", stages(W), W, true);
        Verilog::Custom(v + &format!("always @(*) px = turned[{}:0];\n", P - 1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::{settle, tick};

    /// A few pseudo-random pixel words of `w` bits (xorshift; no dependency needed).
    fn words(n: usize, w: usize, seed: u64) -> Vec<u64> {
        let mut s = seed;
        (0..n)
            .map(|_| {
                s ^= s << 13;
                s ^= s >> 7;
                s ^= s << 17;
                s & ((1 << w) - 1)
            })
            .collect()
    }

    /// Bit planes written one per clock read back as the pixels' words, port group by
    /// port group (the new-z block's corner turn), for two word widths and region sizes.
    fn planes_to_words<const W: usize, const P: usize>() {
        let mut u = PlanesToWords::<W, P>::default();
        u.connect_all();
        let z = words(P, W, 7 + W as u64);
        for b in 0..W {
            u.we.next = true;
            u.plane.next = (b as u64).into();
            u.px.next = (0..P).fold(0u128, |v, x| v | ((z[x] >> b & 1) as u128) << x).to_bits();
            tick(&mut u, |u| &mut u.clock);
        }
        // The last plane lands at the next edge.
        u.we.next = false;
        tick(&mut u, |u| &mut u.clock);
        for g in 0..P / 4 {
            u.group.next = (g as u64).into();
            settle(&mut u);
            let got = [u.w0.val(), u.w1.val(), u.w2.val(), u.w3.val()].map(|w| w.to_u128() as u64);
            assert_eq!(got, [z[4 * g], z[4 * g + 1], z[4 * g + 2], z[4 * g + 3]], "W = {W}, P = {P}, group {g}");
        }
    }

    /// Port groups written one per clock read back as bit planes (the old-z block's).
    fn words_to_planes<const W: usize, const P: usize>() {
        let mut u = WordsToPlanes::<W, P>::default();
        u.connect_all();
        let z = words(P, W, 11 + W as u64);
        for g in 0..P / 4 {
            u.we.next = true;
            u.group.next = (g as u64).into();
            u.d0.next = (z[4 * g] as u128).to_bits();
            u.d1.next = (z[4 * g + 1] as u128).to_bits();
            u.d2.next = (z[4 * g + 2] as u128).to_bits();
            u.d3.next = (z[4 * g + 3] as u128).to_bits();
            tick(&mut u, |u| &mut u.clock);
        }
        u.we.next = false;
        for b in 0..W {
            u.plane.next = (b as u64).into();
            tick(&mut u, |u| &mut u.clock);
            let want = (0..P).fold(0u128, |v, x| v | ((z[x] >> b & 1) as u128) << x);
            assert_eq!(u.px.val().to_u128(), want, "W = {W}, P = {P}, plane {b}");
        }
    }

    #[test]
    fn corner_turns_transpose_pixels_and_bits() {
        planes_to_words::<24, 64>();
        planes_to_words::<16, 64>();
        planes_to_words::<29, 8>();
        words_to_planes::<24, 64>();
        words_to_planes::<29, 64>();
        words_to_planes::<16, 8>();
    }
}
