//! The edge painting tree (paper 002): rust-hdl and Verilator in lockstep, one command
//! per cycle, every mask checked against `model::ept`.

use model::ept::{ept, EptIn};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::ept::{Ept, EptSize, Pixels};
use testbenches::{count, seed, target_dir, write_if_changed, Dual, Mismatch, Value, Verilated};

/// 002 Fig. 5: P = 8, XL = 000, XR = 101 paints PX0..PX5 (pixel i = bit i).
const FIG5: (u32, u32, u128) = (0b000, 0b101, 0b0011_1111);

/// The EPT for `p` pixels, emitted (for the default P: the committed `hdl-out/ept.v`).
fn verilog(p: u64) -> Verilated {
    let unit = rtl::Unit::named("ept").expect("ept is in UNITS");
    let e = unit.emit(&unit.params([("P".to_owned(), p)]).expect("P is ept's parameter")).expect("supported P");
    testbenches::verilate(&e).unwrap_or_else(|e| panic!("{e}"))
}

/// Runs each (XL, XR) for one cycle in both simulators and checks `px` against the model.
fn run<const P: usize>(dual: &mut Dual<Ept<P>>, pairs: impl IntoIterator<Item = (u32, u32)>) -> Result<(), Mismatch>
where
    Pixels<P>: EptSize,
{
    let b = P.trailing_zeros() as usize;
    for (xl, xr) in pairs {
        let out = dual.cycle(&[("xl", Value::new(b, xl.into())), ("xr", Value::new(b, xr.into()))])?;
        dual.expect(&out, "px", &Value::from_bools(&ept(P, EptIn { xl, xr }).px))?;
    }
    Ok(())
}

fn exhaustive<const P: usize>()
where
    Pixels<P>: EptSize,
{
    let vl = verilog(P as u64);
    let mut dual = Dual::new(Ept::<P>::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let n = P as u32;
    run::<P>(&mut dual, (0..n).flat_map(|xl| (0..n).map(move |xr| (xl, xr)))).unwrap_or_else(|m| panic!("{m}"));
    assert_eq!(dual.cycles(), (P * P) as u64);
}

#[test]
fn ept_paper_002_fig5() {
    let vl = verilog(8);
    let mut dual = Dual::new(Ept::<8>::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let (xl, xr, mask) = FIG5;
    let out = dual
        .cycle(&[("xl", Value::new(3, xl.into())), ("xr", Value::new(3, xr.into()))])
        .unwrap_or_else(|m| panic!("{m}"));
    assert_eq!(out.get("px"), &Value::new(8, mask), "both simulators, 002 Fig. 5");
    assert_eq!(Value::from_bools(&ept(8, EptIn { xl, xr }).px), Value::new(8, mask), "model, 002 Fig. 5");
}

#[test]
fn ept_exhaustive_p8() {
    exhaustive::<8>();
}

#[test]
fn ept_exhaustive_p16() {
    exhaustive::<16>();
}

#[test]
fn ept_exhaustive_p64() {
    exhaustive::<64>();
}

/// Every (XL, XR) at 002's largest tree, 1,048,576 cycles (`scripts/soak.sh`).
#[test]
#[ignore = "long: scripts/soak.sh runs it"]
fn ept_exhaustive_p1024() {
    exhaustive::<1024>();
}

/// Random (XL, XR) at P = 1024, a quarter of them with XL > XR (nothing painted) and a
/// quarter on the edges 0, 1023 and the subtree borders (multiples of 4 and 4k - 1):
/// `EDGEPAINT_N` / 4 pairs (250 in the test command, which runs P = 8, 16 and 64
/// exhaustively; 2,500 in the soak's random step, beside P = 1024 exhaustively).
#[test]
fn ept_random_p1024() {
    let (seed, n) = (seed(), count() / 4);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let pick = |rng: &mut ChaCha8Rng| -> u32 {
        match rng.gen_range(0..4) {
            0 => [0, 1023][rng.gen_range(0..2)],
            1 => rng.gen_range(0..256) * 4 + [0, 3][rng.gen_range(0..2)],
            _ => rng.gen_range(0..1024),
        }
    };
    let pairs: Vec<(u32, u32)> = (0..n).map(|_| (pick(&mut rng), pick(&mut rng))).collect();
    let vl = verilog(1024);
    let mut dual = Dual::new(Ept::<1024>::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    run::<1024>(&mut dual, pairs.iter().copied()).unwrap_or_else(|m| {
        let (xl, xr) = pairs[m.cycle as usize];
        panic!("{m}\nseed {seed}: EptIn {{ xl: {xl}, xr: {xr} }}")
    });
}

/// The harness must catch a broken unit: `hdl-out/ept.v` with the root PE's (0, 1) case
/// routing RLC = 0 instead of 1, against the intact rust-hdl unit. The first three
/// commands never reach that case; the fourth (XL = 3 < 32 <= XR = 40) does.
#[test]
fn ept_harness_catches_mutated_verilog() {
    let good = std::fs::read_to_string(testbenches::hdl_out().join("ept.v")).expect("hdl-out/ept.v");
    let start = good.find("module ept$root$pe(").expect("the root PE's module");
    let end = start + good[start..].find("endmodule").expect("its end");
    let root_pe = &good[start..end];
    assert_eq!(root_pe.matches("rlc = 1'b1;").count(), 1, "one constant RLC = 1, in case (0, 1)");
    let bad = format!("{}{}{}", &good[..start], root_pe.replace("rlc = 1'b1;", "rlc = 1'b0;"), &good[end..]);
    let file = write_if_changed(&target_dir().join("hdl").join("ept-mutated"), "ept.v", &bad).expect("mutated Verilog");

    let unit = Ept::<64>::default();
    let vl = Verilated::new("ept", &file, &rtl::emit::ports(&unit)).unwrap_or_else(|e| panic!("{e}"));
    let mut dual = Dual::new(unit, vl.model().unwrap_or_else(|e| panic!("{e}")));
    let m =
        run::<64>(&mut dual, [(0, 0), (5, 9), (40, 50), (3, 40), (0, 63)]).expect_err("the mutation must be caught");
    assert_eq!((m.cycle, m.signal.as_str()), (3, "px"), "{m}");
    let model = Value::from_bools(&ept(64, EptIn { xl: 3, xr: 40 }).px);
    assert_eq!(m.values[0], ("rust-hdl".to_owned(), model.clone()), "{m}");
    assert!(m.values[1].0 == "verilator" && m.values[1].1 != model, "{m}");
    assert!(
        m.to_string().starts_with("ept: cycle 3: px differs: rust-hdl 64'h000001fffffffff8; verilator 64'h"),
        "{m}"
    );
}
