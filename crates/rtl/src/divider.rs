//! `divider`: the one shared pipelined divider of paper 001 (Woo 2004, §II.2.라: "the
//! seven divisions of setup share one 5-stage pipelined divider"). Triangle setup issues
//! its seven divisions into it one per cycle (see `triangle_setup`).
//!
//! It is a radix-2 restoring divider: `QM` quotient bits, one per step, the steps spread
//! over `latency` pipeline stages (stage `s` does steps `s*QM/L .. (s+1)*QM/L`, rounded
//! down; with more stages than steps, some stages are registers only). Where 001's Taylor-series divider is off by up to 1 LSB, this one is exact, as
//! `model::divider::divider` is: `q = floor(n / d)`, `r = n - q*d` in `[0, d)`.
//!
//! ```text
//!  n (signed), d > 0
//!      |  m = n < 0 ? !n : n  (= -n - 1 >= 0)      floor(n/d) for n < 0 is !floor(m/d),
//!      v                                            remainder d - 1 - (m mod d)
//!  [p | x] = [m >> QM | m mod 2^QM]   p: partial remainder (D bits), x: dividend bits
//!      |                                           still to come, quotient bits shifted in
//!  step: t = 2p + msb(x) (D + 1 bits); t - d borrows? p = t, bit = 0 : p = t - d, bit = 1;
//!        x = (x << 1) | bit                        (one subtractor per step: its borrow decides)
//!      |   ... QM steps over L stages, a register after each stage ...
//!      v
//!  q = neg ? !x : x (Q = QM + 1 bits),  r = neg ? d - 1 - p : p  (in the last stage, registered)
//! ```
//!
//! Contract (`model::divider::divider` asserts it): `d` in `[1, 2^D)`, `n` an `N`-bit
//! two's complement number, and the quotient fits `Q` bits (`m < d * 2^QM`).
//!
//! Stream: `inp_valid`/`inp_ready` in, `out_valid`/`out_ready` out; a division taken in
//! cycle t is at the output in cycle t + L (latency `L` = `model::divider::LATENCY` = 25
//! by default: one step a stage at size class 10), one per cycle (II 1). The pipeline advances unless its output is valid and
//! not taken (`inp_ready = !out_valid | out_ready`), or `hold` is high: setup always takes
//! the output and holds the whole pipeline, bubbles too, while it waits for the edge walk.
//!
//! Model: `model::divider`. Emitted: `hdl-out/divider.v` at the widths of
//! `Formats::derived` (`div_dividend_bits`, `div_divisor_bits`, `div_quotient_bits`).

use super::widths::WIDTHS;
use crate::emit::{ports, verilog, Emitted};
use crate::sim::{PinValue, Pins, Value};
use crate::Params;
/// The deepest divider built (`model::divider::LATENCY_MAX`).
pub const LATENCY_MAX: usize = model::divider::LATENCY_MAX as usize;
use blank::Blank;
use rust_hdl::prelude::*;

/// Dividend bits of the emitted divider (`div_dividend_bits`).
pub const DIV_N: usize = WIDTHS.div_n;
/// Divisor and remainder bits (`div_divisor_bits`).
pub const DIV_D: usize = WIDTHS.div_d;
/// Quotient bits, signed (`div_quotient_bits`).
pub const DIV_Q: usize = WIDTHS.div_q;
/// Quotient magnitude bits: one restoring step each.
pub const DIV_QM: usize = DIV_Q - 1;

/// The divider at the widths the RTL is built with.
pub type DividerRtl = Divider<DIV_N, DIV_D, { DIV_D + 1 }, DIV_Q, DIV_QM>;

/// One pipeline stage: `steps` restoring steps on the partial remainder `p` and the
/// dividend/quotient bits `x`, then a register for each (held while `enable` is low).
/// `D1` = `D + 1`: a step's `2p + 1` and its difference with `d` (stable Rust cannot
/// write `D + 1` as a width).
#[derive(LogicBlock, Blank)]
pub struct DivStage<const D: usize, const D1: usize, const QM: usize> {
    pub clock: Signal<In, Clock>,
    /// Advance the pipeline this cycle.
    pub enable: Signal<In, Bit>,
    pub valid_in: Signal<In, Bit>,
    pub p_in: Signal<In, Bits<D>>,
    pub x_in: Signal<In, Bits<QM>>,
    pub d_in: Signal<In, Bits<D>>,
    pub neg_in: Signal<In, Bit>,
    /// The registered results of this stage's steps, and the divisor and sign passed on.
    pub valid: Signal<Out, Bit>,
    pub p: Signal<Out, Bits<D>>,
    pub x: Signal<Out, Bits<QM>>,
    pub d: Signal<Out, Bits<D>>,
    pub neg: Signal<Out, Bit>,
    valid_r: DFF<Bit>,
    p_r: DFF<Bits<D>>,
    x_r: DFF<Bits<QM>>,
    d_r: DFF<Bits<D>>,
    neg_r: DFF<Bit>,
    /// `p` (`D1` bits, the top one 0) and `x` before step i (entry `steps`: after the last).
    tp: Vec<Signal<Local, Bits<D1>>>,
    tx: Vec<Signal<Local, Bits<QM>>>,
    /// Step i's `2p + msb(x)` and `2p + msb(x) - d`.
    t: Vec<Signal<Local, Bits<D1>>>,
    diff: Vec<Signal<Local, Bits<D1>>>,
    /// The divisor in `D1` bits.
    d1: Signal<Local, Bits<D1>>,
    /// Bit indices: the borrow of a difference (`D`), the MSB of `x` (`QM - 1`).
    borrow: Constant<Bits<8>>,
    x_msb: Constant<Bits<8>>,
    /// The last stage: it registers the result, a negative dividend's corrected
    /// (`r = d - 1 - p`, `q = !x`), so that the divider's outputs are registers.
    fin: Constant<Bit>,
    _steps: usize,
}

impl<const D: usize, const D1: usize, const QM: usize> DivStage<D, D1, QM> {
    fn new(steps: usize, fin: bool) -> Self {
        assert_eq!(D1, D + 1, "DivStage: D1 is D + 1");
        Self {
            tp: (0..=steps).map(|_| Default::default()).collect(),
            tx: (0..=steps).map(|_| Default::default()).collect(),
            t: (0..steps).map(|_| Default::default()).collect(),
            diff: (0..steps).map(|_| Default::default()).collect(),
            borrow: Constant::new(D.to_bits()),
            x_msb: Constant::new((QM - 1).to_bits()),
            fin: Constant::new(fin),
            _steps: steps,
            ..Self::blank()
        }
    }
}

impl<const D: usize, const D1: usize, const QM: usize> Logic for DivStage<D, D1, QM> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, valid_r, p_r, x_r, d_r, neg_r);
        self.d1.next = bit_cast::<D1, D>(self.d_in.val());
        self.tp[0].next = bit_cast::<D1, D>(self.p_in.val());
        self.tx[0].next = self.x_in.val();
        for i in 0..self._steps {
            self.t[i].next = self.tp[i].val() << 1;
            if self.tx[i].val().get_bit(self.x_msb.val().index()) {
                self.t[i].next = (self.tp[i].val() << 1) | 1;
            }
            // t < 2d < 2^D1: t - d borrows (its bit D is set) exactly when t < d.
            self.diff[i].next = self.t[i].val() - self.d1.val();
            if self.diff[i].val().get_bit(self.borrow.val().index()) {
                self.tp[i + 1].next = self.t[i].val();
                self.tx[i + 1].next = self.tx[i].val() << 1;
            } else {
                self.tp[i + 1].next = self.diff[i].val();
                self.tx[i + 1].next = (self.tx[i].val() << 1) | 1;
            }
        }
        if self.enable.val() {
            self.valid_r.d.next = self.valid_in.val();
            for i in self._steps..(self._steps + 1) {
                self.p_r.d.next = self.tp[i].val().get_bits::<D>(0);
                self.x_r.d.next = self.tx[i].val();
                if self.fin.val() & self.neg_in.val() {
                    self.p_r.d.next = self.d_in.val() - self.tp[i].val().get_bits::<D>(0) - 1;
                    self.x_r.d.next = !self.tx[i].val();
                }
            }
            self.d_r.d.next = self.d_in.val();
            self.neg_r.d.next = self.neg_in.val();
        }
        self.valid.next = self.valid_r.q.val();
        self.p.next = self.p_r.q.val();
        self.x.next = self.x_r.q.val();
        self.d.next = self.d_r.q.val();
        self.neg.next = self.neg_r.q.val();
    }
}

/// The pipelined floor divider: `N`-bit signed dividend, `D`-bit divisor and remainder,
/// `Q`-bit signed quotient (`QM = Q - 1` steps; `D1 = D + 1`). See the module
/// documentation.
#[derive(LogicBlock, Blank)]
pub struct Divider<const N: usize, const D: usize, const D1: usize, const Q: usize, const QM: usize> {
    pub clock: Signal<In, Clock>,
    pub inp_valid: Signal<In, Bit>,
    /// `!hold & (!out_valid | out_ready)`: the pipeline advances.
    pub inp_ready: Signal<Out, Bit>,
    /// Hold every stage this cycle (nothing is taken).
    pub hold: Signal<In, Bit>,
    /// Dividend, two's complement.
    pub inp_n: Signal<In, Bits<N>>,
    /// Divisor, unsigned, at least 1.
    pub inp_d: Signal<In, Bits<D>>,
    pub out_valid: Signal<Out, Bit>,
    pub out_ready: Signal<In, Bit>,
    /// `floor(n / d)`, two's complement.
    pub out_q: Signal<Out, Bits<Q>>,
    /// `n - q*d`, in `[0, d)`.
    pub out_r: Signal<Out, Bits<D>>,
    stages: Vec<DivStage<D, D1, QM>>,
    /// The pipeline advances this cycle.
    advance: Signal<Local, Bit>,
    /// `n`, or `!n` for a negative `n`.
    m: Signal<Local, Bits<N>>,
    /// The last stage's quotient bits, before the sign fix.
    last_x: Signal<Local, Bits<QM>>,
    /// Bit index of the dividend's sign (`N - 1`), and `QM` (the shift that leaves the
    /// dividend's top bits for the first partial remainder).
    n_msb: Constant<Bits<8>>,
    qm: Constant<Bits<8>>,
    /// The quotient's sign bit (`2^QM`).
    q_sign: Constant<Bits<Q>>,
    _latency: usize,
}

impl<const N: usize, const D: usize, const D1: usize, const Q: usize, const QM: usize> Divider<N, D, D1, Q, QM> {
    /// A divider of `latency` stages (1 to `QM`).
    pub fn new(latency: usize) -> Self {
        assert_eq!(Q, QM + 1, "the quotient is QM magnitude bits and a sign");
        assert!(N - 1 <= QM + D, "the dividend's top N-1-QM bits must fit the D-bit partial remainder");
        assert!(
            (1..=LATENCY_MAX).contains(&latency),
            "divider latency {latency} must be 1 to {LATENCY_MAX} (past {QM}, stages without steps)"
        );
        let stages =
            (0..latency).map(|s| DivStage::new((s + 1) * QM / latency - s * QM / latency, s + 1 == latency)).collect();
        Self {
            stages,
            n_msb: Constant::new((N - 1).to_bits()),
            qm: Constant::new(QM.to_bits()),
            q_sign: Constant::new((1u128 << QM).to_bits()),
            _latency: latency,
            ..Self::blank()
        }
    }

    /// Pipeline stages: the latency in cycles.
    pub fn latency(&self) -> usize {
        self._latency
    }
}

impl<const N: usize, const D: usize, const D1: usize, const Q: usize, const QM: usize> Logic
    for Divider<N, D, D1, Q, QM>
{
    #[hdl_gen]
    fn update(&mut self) {
        // The last stage, selected by a loop of one iteration: rust-hdl evaluates array
        // indices from loop variables and literals only.
        for s in (self._latency - 1)..self._latency {
            self.advance.next = !self.hold.val() & (!self.stages[s].valid.val() | self.out_ready.val());
            self.out_valid.next = self.stages[s].valid.val();
            self.last_x.next = self.stages[s].x.val();
            // The last stage registered the corrected result; the sign is the dividend's.
            self.out_r.next = self.stages[s].p.val();
            self.out_q.next = bit_cast::<Q, QM>(self.last_x.val());
            if self.stages[s].neg.val() {
                self.out_q.next = bit_cast::<Q, QM>(self.last_x.val()) | self.q_sign.val();
            }
        }
        for s in 0..self._latency {
            self.stages[s].clock.next = self.clock.val();
            self.stages[s].enable.next = self.advance.val();
        }
        self.inp_ready.next = self.advance.val();
        self.m.next = self.inp_n.val();
        if self.inp_n.val().get_bit(self.n_msb.val().index()) {
            self.m.next = !self.inp_n.val();
        }
        self.stages[0].valid_in.next = self.inp_valid.val();
        self.stages[0].p_in.next = bit_cast::<D, N>(self.m.val() >> self.qm.val());
        self.stages[0].x_in.next = self.m.val().get_bits::<QM>(0);
        self.stages[0].d_in.next = self.inp_d.val();
        self.stages[0].neg_in.next = self.inp_n.val().get_bit(self.n_msb.val().index());
        for s in 1..self._latency {
            self.stages[s].valid_in.next = self.stages[s - 1].valid.val();
            self.stages[s].p_in.next = self.stages[s - 1].p.val();
            self.stages[s].x_in.next = self.stages[s - 1].x.val();
            self.stages[s].d_in.next = self.stages[s - 1].d.val();
            self.stages[s].neg_in.next = self.stages[s - 1].neg.val();
        }
    }
}

/// Written out rather than through `pins!`, which takes no generic parameters: the tests
/// drive a narrow divider too.
impl<const N: usize, const D: usize, const D1: usize, const Q: usize, const QM: usize> Pins
    for Divider<N, D, D1, Q, QM>
{
    fn set(&mut self, pin: &str, value: &Value) {
        match pin {
            "inp_valid" => self.inp_valid.next = PinValue::from_value(value),
            "inp_n" => self.inp_n.next = PinValue::from_value(value),
            "inp_d" => self.inp_d.next = PinValue::from_value(value),
            "out_ready" => self.out_ready.next = PinValue::from_value(value),
            "hold" => self.hold.next = PinValue::from_value(value),
            _ => panic!("divider has no input pin {pin}"),
        }
    }
    fn get(&self, pin: &str) -> Value {
        match pin {
            "inp_ready" => self.inp_ready.val().to_value(),
            "out_valid" => self.out_valid.val().to_value(),
            "out_q" => self.out_q.val().to_value(),
            "out_r" => self.out_r.val().to_value(),
            _ => panic!("divider has no output pin {pin}"),
        }
    }
    fn clock(&mut self) -> Option<&mut Signal<In, Clock>> {
        Some(&mut self.clock)
    }
}

/// Emits a divider of `latency` stages at any widths, as unit `divider` (the tests' narrow
/// divider goes through here too).
pub fn emit<const N: usize, const D: usize, const D1: usize, const Q: usize, const QM: usize>(
    latency: usize,
    params: &Params,
) -> Emitted {
    let mut u = Divider::<N, D, D1, Q, QM>::new(latency);
    u.connect_all();
    Emitted {
        unit: "divider",
        params: params.clone(),
        formats: None,
        ports: ports(&u),
        verilog: verilog("divider", &u),
        dir: None,
    }
}

/// `UNITS` entry: the divider at the RTL's widths with `params["L"]` stages.
pub fn emit_divider(params: &Params) -> Result<Emitted, String> {
    let l = params["L"] as usize;
    if !(1..=LATENCY_MAX).contains(&l) {
        return Err(format!("divider: L = {l} is not supported: 1 to {LATENCY_MAX} stages"));
    }
    Ok(emit::<DIV_N, DIV_D, { DIV_D + 1 }, DIV_Q, DIV_QM>(l, params))
}
