//! The shared divider (paper 001): rust-hdl and Verilator in lockstep against
//! `model::divider::divider`, exhaustively at a narrow width and at random at the full one,
//! with the error bound measured; latency and initiation interval against the model's.
//!
//! The narrow divider is the same generic `Divider` with 8-bit dividends and 7-bit
//! divisors: the same steps, stage split and sign fix, few enough inputs to try them all.

use model::divider::{divider, recip_operands, DividerIn, DividerOut, II, LATENCY};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::divider::{emit, Divider, DIV_D, DIV_N, DIV_Q, DIV_QM};
use rtl::widths::{DERIVED, FORMATS};
use std::collections::VecDeque;
use testbenches::flow::{hdl_cycle, outputs, Cycle, Flow};
use testbenches::streams::{raw, signed};
use testbenches::{count, seed, verilated, Dual, HdlSim, Pins, Value, Verilated};

/// What a run measured: the cycle each division was taken and came out, and the largest
/// `n/d - q` (floor division: in [0, 1) LSB of q).
struct Run {
    taken: Vec<u64>,
    out: Vec<u64>,
    max_error_lsb: f64,
}

/// Drives `divs` through `cycle` (one clock of one or both simulators) at widths
/// (n, d, q) and checks each result against the model and an independent oracle.
fn run(
    cycle: &mut Cycle,
    widths: (usize, usize, usize),
    divs: &[DividerIn],
    flow: Flow,
    rng: &mut ChaCha8Rng,
) -> Result<Run, String> {
    let (wn, wd, _) = widths;
    let mut r = Run { taken: vec![0; divs.len()], out: vec![0; divs.len()], max_error_lsb: 0.0 };
    let (mut next, mut presenting, mut ready, mut done, mut now) = (0, false, true, 0, 0u64);
    let mut in_flight = VecDeque::new();
    while done < divs.len() {
        if now > 10 * divs.len() as u64 + 100 {
            return Err(format!("{done} of {} divisions out after {now} cycles", divs.len()));
        }
        if next < divs.len() {
            presenting = flow.offer(presenting, rng);
        }
        let i = next.min(divs.len() - 1);
        let pins = [
            ("inp_valid", Value::new(1, presenting as u128)),
            ("inp_n", raw(wn, divs[i].n)),
            ("inp_d", raw(wd, divs[i].d)),
            ("out_ready", Value::new(1, ready as u128)),
        ];
        let out = cycle(&pins)?;
        if out.get("out_valid").bit(0) && ready {
            let k: usize = in_flight.pop_front().ok_or(format!("cycle {now}: a result with no division in flight"))?;
            let DividerIn { n, d } = divs[k];
            let got = DividerOut { q: signed(out.get("out_q")), r: out.get("out_r").to_u128() as i128 };
            let model = divider(divs[k], &FORMATS);
            if got != model {
                return Err(format!("cycle {now}: {n} / {d}: RTL {got:?}, model {model:?} (inputs {pins:?})"));
            }
            // Independent oracle: q*d <= n < (q+1)*d, r = n - q*d.
            if !(got.q * d <= n && n < (got.q + 1) * d && got.r == n - got.q * d) {
                return Err(format!("{n} / {d} gave {got:?}: not floor division"));
            }
            r.max_error_lsb = r.max_error_lsb.max(got.r as f64 / d as f64);
            r.out[k] = now;
            done += 1;
        }
        if presenting && out.get("inp_ready").bit(0) {
            r.taken[next] = now;
            in_flight.push_back(next);
            next += 1;
            presenting = false;
        }
        ready = flow.next_ready(ready, rng);
        now += 1;
    }
    Ok(r)
}

/// `divs` through rust-hdl and Verilator in lockstep.
fn dual<const N: usize, const D: usize, const D1: usize, const Q: usize, const QM: usize>(
    vl: &Verilated,
    latency: usize,
    divs: &[DividerIn],
    flow: Flow,
) -> Run
where
    Divider<N, D, D1, Q, QM>: Pins,
{
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut dual = Dual::new(Divider::<N, D, D1, Q, QM>::new(latency), vl.model().unwrap_or_else(|e| panic!("{e}")));
    run(&mut |p| dual.cycle(p).map_err(|m| m.to_string()), (N, D, Q), divs, flow, &mut rng)
        .unwrap_or_else(|e| panic!("{e}\nseed {seed}"))
}

/// `divs` through rust-hdl's simulator alone (no Verilator build per latency).
fn hdl_only<const N: usize, const D: usize, const D1: usize, const Q: usize, const QM: usize>(
    latency: usize,
    divs: &[DividerIn],
    flow: Flow,
) -> Run
where
    Divider<N, D, D1, Q, QM>: Pins,
{
    let mut sim = HdlSim::new(Divider::<N, D, D1, Q, QM>::new(latency));
    let outs = outputs(&sim.unit);
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut cycle = |pins: &[(&str, Value)]| Ok(hdl_cycle(&mut sim, &outs, pins));
    run(&mut cycle, (N, D, Q), divs, flow, &mut rng).unwrap_or_else(|e| panic!("{e}\nseed {}", seed()))
}

/// Every 8-bit dividend by every 7-bit divisor.
fn all_narrow() -> Vec<DividerIn> {
    (-128..128).flat_map(|n| (1..128).map(move |d| DividerIn { n, d })).collect()
}

/// The narrow divider with `latency` stages, emitted under the target directory.
fn narrow_verilog(latency: usize) -> Verilated {
    let params = [("L".to_owned(), latency as u64), ("N".to_owned(), 8)].into();
    testbenches::verilate(&emit::<8, 7, 8, 9, 8>(latency, &params)).unwrap_or_else(|e| panic!("{e}"))
}

/// Exhaustive at the narrow width, in both simulators, with three stages (an uneven
/// split of the 8 steps: 2, 3, 3) and with stalls; the error bound measured: exact floor,
/// `0 <= n/d - q < 1` LSB.
#[test]
fn divider_exhaustive_w8_is_floor_division() {
    let divs = all_narrow();
    let r = dual::<8, 7, 8, 9, 8>(&narrow_verilog(3), 3, &divs, Flow::STALLING);
    assert!(r.max_error_lsb < 1.0);
    eprintln!("divider, every 8-bit / 7-bit division: max n/d - q = {:.4} LSB (floor: < 1)", r.max_error_lsb);
}

/// Exhaustive at the narrow width for other depths, in rust-hdl's simulator: one stage,
/// 001's five, one step per stage, and more stages than steps (registers only).
#[test]
fn divider_exhaustive_w8_other_latencies_rust_hdl() {
    let divs = all_narrow();
    for latency in [1, 5, 8, 11] {
        let r = hdl_only::<8, 7, 8, 9, 8>(latency, &divs, Flow::BACK_TO_BACK);
        assert!(r.taken.iter().zip(&r.out).all(|(t, o)| o - t == latency as u64), "L = {latency}");
    }
}

/// The divisions setup issues (model::divider): reciprocals of twice the area (any size),
/// edge starts `(x fraction * dy + dx * t) / (2^s dy)` and steps `dx / dy`, and divisions
/// filling the contract (any divisor, any quotient that fits).
fn random_full_width(rng: &mut ChaCha8Rng, n: usize) -> Vec<DividerIn> {
    let dv = DERIVED;
    let (s, delta) = (FORMATS.xy.frac, 1i128 << (dv.delta_bits - 1));
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let div = match rng.gen_range(0..4) {
            0 => {
                recip_operands(
                    (rng.gen_range(1..=1i128 << (dv.area_bits - 2)) >> rng.gen_range(0..32)).max(1),
                    &FORMATS,
                )
                .0
            }
            1 => {
                let (dx, dy) = (rng.gen_range(-delta + 1..delta), rng.gen_range(1..delta));
                let (xf, t) = (rng.gen_range(0..1i128 << s), rng.gen_range(-(1i128 << s)..1i128 << s));
                DividerIn { n: xf * dy + dx * t, d: dy << s }
            }
            2 => DividerIn { n: rng.gen_range(-delta + 1..delta), d: rng.gen_range(1..delta) >> rng.gen_range(0..16) },
            _ => {
                let d =
                    (rng.gen_range(1..1i128 << dv.div_divisor_bits) >> rng.gen_range(0..dv.div_divisor_bits)).max(1);
                let q = rng.gen_range(-(1i128 << (dv.div_quotient_bits - 1))..1i128 << (dv.div_quotient_bits - 1));
                DividerIn { n: q * d + rng.gen_range(0..d), d }
            }
        };
        let fits = |v: i128, bits: u32| -(1i128 << (bits - 1)) <= v && v < 1i128 << (bits - 1);
        if div.d >= 1 && fits(div.n, dv.div_dividend_bits) && fits(div.n.div_euclid(div.d), dv.div_quotient_bits) {
            out.push(div);
        }
    }
    out
}

/// Random at the full width (`hdl-out/divider.v`, 25 stages), in both simulators, with
/// stalls; the error bound measured, also as a reciprocal (OneOverArea's mantissa).
#[test]
fn divider_random_full_width_is_floor_division() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut divs = random_full_width(&mut rng, count() * 10);
    // The extremes: the largest dividend and quotient magnitudes, divisor 1 and the largest.
    let (nlim, dmax, qlim) = (1i128 << (DIV_N - 1), (1i128 << DIV_D) - 1, 1i128 << DIV_QM);
    divs.extend([
        DividerIn { n: -qlim, d: 1 },
        DividerIn { n: qlim - 1, d: 1 },
        DividerIn { n: nlim - 1, d: dmax },
        DividerIn { n: -nlim, d: dmax },
        DividerIn { n: 0, d: 1 },
        DividerIn { n: -1, d: dmax },
    ]);
    let vl = verilated("divider");
    let r = dual::<DIV_N, DIV_D, { DIV_D + 1 }, DIV_Q, DIV_QM>(&vl, LATENCY as usize, &divs, Flow::STALLING);
    assert!(r.max_error_lsb < 1.0);
    eprintln!(
        "divider, {} random full-width divisions: max n/d - q = {:.6} LSB (floor: < 1)",
        divs.len(),
        r.max_error_lsb
    );
}

/// 001 §II.2.라: one pipelined divider, a division taken every cycle (001's has 5 stages;
/// the default here one quotient step a stage, 25 at class 10). Back to back, each result
/// comes out `LATENCY` cycles after its division is taken.
#[test]
fn divider_latency_and_ii_paper_001() {
    assert_eq!((LATENCY, II), (DIV_QM as u32, 1));
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let divs = random_full_width(&mut rng, 100);
    let vl = verilated("divider");
    let r = dual::<DIV_N, DIV_D, { DIV_D + 1 }, DIV_Q, DIV_QM>(&vl, LATENCY as usize, &divs, Flow::BACK_TO_BACK);
    for (i, w) in r.taken.windows(2).enumerate() {
        assert_eq!(w[1] - w[0], II as u64, "divisions {i} and {} taken back to back", i + 1);
    }
    for (i, (t, o)) in r.taken.iter().zip(&r.out).enumerate() {
        assert_eq!(o - t, LATENCY as u64, "division {i}");
    }
}
