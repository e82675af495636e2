//! The dual-simulation harness: one unit, the same per-cycle stimulus, two simulators.
//!
//! * [`HdlSim`] steps the rust-hdl unit directly (`simulate`, as `rtl::sim::tick` does;
//!   not rust-hdl's threaded `Simulation`).
//! * [`VlSim`] runs the unit's emitted Verilog under Verilator, in-process through marlin's
//!   dynamic models; [`Verilated`] builds it under `<target>/verilator/`.
//!
//! [`Dual::cycle`] drives both with the same inputs, compares every output of the two after
//! the inputs settle, then clocks both (clocked units); [`Dual::expect`] compares an output
//! with the bit-exact model's value. Either reports a [`Mismatch`]: the cycle, the signal,
//! each side's value and the inputs of that cycle.
//!
//! A unit plugs in through `rtl::sim::Pins` (its pins by Verilog name, values as
//! [`Value`]s of any width, so >64-bit ports work) and `rtl::emit::ports` (the port list,
//! read off the rust-hdl struct). A clocked unit's clock is the port named `clock`;
//! valid/ready pipelines drive `ready` like any input, cycle by cycle, and expect outputs
//! only on the cycles the model says are valid.

pub mod flow;
pub mod frame;
pub mod memory;
pub mod stimulus;
pub mod streams;
mod verilated;

pub use rtl::emit::Port;
pub use rtl::sim::{Pins, PortDir, Value};
pub use verilated::{check_verilator, target_dir, write_if_changed, Verilated, VlSim};

use rust_hdl::prelude::*;
use std::fmt;
use std::path::PathBuf;

/// One simulator of one unit.
pub trait Sim {
    /// Which simulator, for messages.
    fn name(&self) -> &'static str;
    /// Drives input `pin`.
    fn set(&mut self, pin: &str, value: &Value);
    /// Propagates the inputs through the combinational logic.
    fn settle(&mut self);
    /// A rising and a falling clock edge, each settled.
    fn clock(&mut self);
    /// Reads output `pin`.
    fn get(&mut self, pin: &str) -> Value;
}

/// A rust-hdl unit, stepped directly.
pub struct HdlSim<U> {
    pub unit: U,
}

impl<U: Block + Pins> HdlSim<U> {
    /// Connects `unit` and runs rust-hdl's checks (open inputs, loops, writes to inputs).
    pub fn new(mut unit: U) -> Self {
        unit.connect_all();
        check_all(&unit).unwrap_or_else(|e| panic!("rust-hdl checks: {e:?}"));
        HdlSim { unit }
    }
}

impl<U: Block + Pins> Sim for HdlSim<U> {
    fn name(&self) -> &'static str {
        "rust-hdl"
    }
    fn set(&mut self, pin: &str, value: &Value) {
        self.unit.set(pin, value);
    }
    fn settle(&mut self) {
        rtl::sim::settle(&mut self.unit);
    }
    fn clock(&mut self) {
        for level in [true, false] {
            self.unit.clock().expect("a clocked unit's Pins::clock").next = level.into();
            self.settle();
        }
    }
    fn get(&mut self, pin: &str) -> Value {
        self.unit.get(pin)
    }
}

/// Outputs of one cycle, by pin name, as both simulators agreed on them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outputs(pub Vec<(String, Value)>);

impl Outputs {
    /// The value of output `pin`; panics on an unknown name.
    pub fn get(&self, pin: &str) -> &Value {
        self.0.iter().find(|(n, _)| n == pin).map(|(_, v)| v).unwrap_or_else(|| panic!("no output {pin}"))
    }
}

/// Two simulators disagreeing, or a simulator disagreeing with the model.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mismatch {
    /// The unit's name.
    pub unit: String,
    /// Cycle number, from 0 at the first [`Dual::cycle`].
    pub cycle: u64,
    /// The output that differs.
    pub signal: String,
    /// Each side's value: ("rust-hdl", …), ("verilator", …) or ("model", …).
    pub values: Vec<(String, Value)>,
    /// The inputs driven in that cycle.
    pub inputs: Vec<(String, Value)>,
}

impl fmt::Display for Mismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: cycle {}: {} differs:", self.unit, self.cycle, self.signal)?;
        for (who, v) in &self.values {
            write!(f, " {who} {v};")?;
        }
        write!(f, " inputs")?;
        for (pin, v) in &self.inputs {
            write!(f, " {pin}={v}")?;
        }
        Ok(())
    }
}

impl std::error::Error for Mismatch {}

/// One unit under rust-hdl and Verilator in lockstep.
pub struct Dual<'rt, U> {
    unit: String,
    hdl: HdlSim<U>,
    vl: VlSim<'rt>,
    ports: Vec<Port>,
    clocked: bool,
    cycle: u64,
    inputs: Vec<(String, Value)>,
}

impl<'rt, U: Block + Pins> Dual<'rt, U> {
    /// `unit` (not yet connected) beside `vl`, the Verilog emitted from the same unit.
    /// Panics if their port lists differ.
    pub fn new(unit: U, vl: VlSim<'rt>) -> Self {
        let hdl = HdlSim::new(unit);
        let ports = rtl::emit::ports(&hdl.unit);
        assert_eq!(ports, vl.ports(), "the rust-hdl unit and the Verilog of {} have different ports", vl.unit());
        let clocked = ports.iter().any(|p| p.name == "clock");
        let inputs = ports
            .iter()
            .filter(|p| p.dir == PortDir::In && p.name != "clock")
            .map(|p| (p.name.clone(), Value::zero(p.width)))
            .collect();
        Dual { unit: vl.unit().to_owned(), hdl, vl, ports, clocked, cycle: 0, inputs }
    }

    /// The next cycle's number.
    pub fn cycles(&self) -> u64 {
        self.cycle
    }

    /// One cycle: drives `inputs` (inputs not named keep their value; all start at zero)
    /// into both simulators, settles, compares every output, then clocks a clocked unit.
    /// Returns the outputs as sampled before the clock edge.
    pub fn cycle(&mut self, inputs: &[(&str, Value)]) -> Result<Outputs, Mismatch> {
        for (pin, v) in inputs {
            let slot = self
                .inputs
                .iter_mut()
                .find(|(n, _)| n == pin)
                .unwrap_or_else(|| panic!("{} has no input {pin}", self.unit));
            assert_eq!(
                slot.1.width(),
                v.width(),
                "{}: {pin} is {} bits wide, not {}",
                self.unit,
                slot.1.width(),
                v.width()
            );
            slot.1 = v.clone();
        }
        for (pin, v) in &self.inputs {
            self.hdl.set(pin, v);
            self.vl.set(pin, v);
        }
        self.hdl.settle();
        self.vl.settle();
        let mut out = Vec::new();
        for p in self.ports.iter().filter(|p| p.dir == PortDir::Out) {
            let (a, b) = (self.hdl.get(&p.name), self.vl.get(&p.name));
            if a != b {
                return Err(self.mismatch(
                    self.cycle,
                    &p.name,
                    vec![(self.hdl.name().into(), a), (self.vl.name().into(), b)],
                ));
            }
            out.push((p.name.clone(), a));
        }
        if self.clocked {
            self.hdl.clock();
            self.vl.clock();
        }
        self.cycle += 1;
        Ok(Outputs(out))
    }

    /// Compares output `pin` of the cycle just run (`got`, from [`Dual::cycle`]) with the
    /// model's value.
    pub fn expect(&self, got: &Outputs, pin: &str, model: &Value) -> Result<(), Mismatch> {
        let v = got.get(pin);
        if v == model {
            return Ok(());
        }
        let both = format!("{} and {}", self.hdl.name(), self.vl.name());
        Err(self.mismatch(self.cycle - 1, pin, vec![(both, v.clone()), ("model".into(), model.clone())]))
    }

    fn mismatch(&self, cycle: u64, signal: &str, values: Vec<(String, Value)>) -> Mismatch {
        Mismatch { unit: self.unit.clone(), cycle, signal: signal.into(), values, inputs: self.inputs.clone() }
    }
}

/// Seed of a random test: `EDGEPAINT_SEED`, default 1. Print it with every failure.
pub fn seed() -> u64 {
    std::env::var("EDGEPAINT_SEED").map_or(1, |s| s.parse().expect("EDGEPAINT_SEED must be a u64"))
}

/// Cases of a random test: `EDGEPAINT_N`, default 1000 (`scripts/soak.sh` sets 100 000).
pub fn count() -> usize {
    std::env::var("EDGEPAINT_N").map_or(1000, |s| s.parse().expect("EDGEPAINT_N must be a count"))
}

/// The committed `hdl-out/` of this checkout.
pub fn hdl_out() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..").join("hdl-out")
}

/// The Verilog of unit `name` with its default parameters, ready for Verilator (the
/// committed `hdl-out/<name>.v` when the default design holds it: see [`Verilated::of`]).
pub fn verilated(name: &str) -> Verilated {
    let unit = rtl::Unit::named(name).unwrap_or_else(|| panic!("no unit {name} in UNITS"));
    let params = unit.params([]).expect("default parameters");
    let e = unit.emit(&params).unwrap_or_else(|e| panic!("{e}"));
    Verilated::of(&e).unwrap_or_else(|e| panic!("{e}"))
}
