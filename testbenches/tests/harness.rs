//! The harness's own tests: a clocked unit with >64-bit ports through both simulators,
//! and the failure when Verilator is missing.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;
use testbenches::{check_verilator, seed, target_dir, write_if_changed, Dual, Pins, Value, Verilated};

/// A 130-bit XOR accumulator with a load enable: on each rising edge, `acc <= acc ^ din`
/// when `en`; `dout` is `acc`. Exercises wide ports both ways, a clock and an enable.
#[derive(LogicBlock, Default)]
struct WideAcc {
    clock: Signal<In, Clock>,
    en: Signal<In, Bit>,
    din: Signal<In, Bits<130>>,
    dout: Signal<Out, Bits<130>>,
    acc: DFF<Bits<130>>,
}

impl Logic for WideAcc {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, acc);
        if self.en.val() {
            self.acc.d.next = self.acc.q.val() ^ self.din.val();
        }
        self.dout.next = self.acc.q.val();
    }
}

impl Pins for WideAcc {
    fn set(&mut self, pin: &str, value: &Value) {
        match pin {
            "en" => self.en.next = value.bit(0),
            "din" => self.din.next = value.to_bits(),
            _ => panic!("no input {pin}"),
        }
    }
    fn get(&self, pin: &str) -> Value {
        match pin {
            "dout" => Value::from_bits(self.dout.val()),
            _ => panic!("no output {pin}"),
        }
    }
    fn clock(&mut self) -> Option<&mut Signal<In, Clock>> {
        Some(&mut self.clock)
    }
}

#[test]
fn harness_wide_clocked_unit_agrees() {
    let mut u = WideAcc::default();
    u.connect_all();
    let (ports, verilog) = (rtl::emit::ports(&u), rtl::emit::verilog("wide_acc", &u));
    let file = write_if_changed(&target_dir().join("hdl").join("wide_acc"), "wide_acc.v", &verilog).expect("Verilog");
    let vl = Verilated::new("wide_acc", &file, &ports).unwrap_or_else(|e| panic!("{e}"));
    let mut dual = Dual::new(WideAcc::default(), vl.model().unwrap_or_else(|e| panic!("{e}")));
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let mut acc = [0u64; 3];
    for _ in 0..500 {
        let din = [rng.gen(), rng.gen(), rng.gen_range(0..4)];
        let en = rng.gen_bool(0.7);
        let out = dual
            .cycle(&[("en", Value::new(1, en as u128)), ("din", Value::from_words(130, &din))])
            .unwrap_or_else(|m| panic!("{m}"));
        dual.expect(&out, "dout", &Value::from_words(130, &acc)).unwrap_or_else(|m| panic!("{m}"));
        if en {
            acc.iter_mut().zip(din).for_each(|(a, d)| *a ^= d);
        }
    }
}

#[test]
fn harness_without_verilator_says_how_to_install() {
    let err = check_verilator("edgepaint-no-such-verilator").expect_err("no such program");
    assert!(err.contains("scripts/setup-tools.sh"), "{err}");
}
