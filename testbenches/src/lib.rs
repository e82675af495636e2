//! The dual-simulation harness: one unit, the same per-cycle stimulus, two simulators.
//!
//! * [`HdlSim`] steps the rust-hdl unit directly (`sim::HdlSim`).
//! * [`VlSim`] runs the unit's emitted Verilog under Verilator, in-process
//!   (`sim::verilator`); [`Verilated`] builds it, cached under `<target>/verilator/`.
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
pub mod stimulus;
pub mod texture;

pub use sim::{check_verilator, verilate, Pins, Port, PortDir, Value, Verilated, VlSim};
pub use sim::{frame, hdl_out, memory, se_frame, streams, target_dir, write_if_changed, HdlSim, Outputs, Sim};

use rust_hdl::prelude::*;
use std::fmt;
use std::sync::Arc;

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
pub struct Dual<U> {
    unit: String,
    hdl: HdlSim<U>,
    vl: VlSim,
    ports: Vec<Port>,
    clocked: bool,
    cycle: u64,
    inputs: Vec<(String, Value)>,
}

impl<U: Block + Pins> Dual<U> {
    /// `unit` (not yet connected) beside `vl`, the Verilog emitted from the same unit.
    /// Panics if their port lists differ.
    pub fn new(unit: U, vl: VlSim) -> Self {
        let hdl = HdlSim::new(unit);
        let ports = rtl::emit::ports(&hdl.unit);
        assert_eq!(
            ports,
            vl.ports().to_vec(),
            "the rust-hdl unit and the Verilog of {} have different ports",
            vl.unit()
        );
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

/// Cases of a random test: `EDGEPAINT_N`, default 1000 (`scripts/soak.sh` sets 10 000).
pub fn count() -> usize {
    std::env::var("EDGEPAINT_N").map_or(1000, |s| s.parse().expect("EDGEPAINT_N must be a count"))
}

/// Unit `name` and `params` over its defaults.
fn unit_params<const K: usize>(name: &str, params: [(&str, u64); K]) -> (&'static rtl::Unit, rtl::Params) {
    let unit = rtl::Unit::named(name).unwrap_or_else(|| panic!("no unit {name} in UNITS"));
    (unit, unit.params(params.map(|(k, v)| (k.to_owned(), v))).unwrap_or_else(|e| panic!("{e}")))
}

/// Unit `name` emitted with `params` over its defaults (at the formats of its size class).
pub fn emitted<const K: usize>(name: &str, params: [(&str, u64); K]) -> rtl::emit::Emitted {
    let (unit, params) = unit_params(name, params);
    unit.emit(&params).unwrap_or_else(|e| panic!("{e}"))
}

/// Unit `name` with its default parameters, Verilated (the committed `hdl-out/<name>.v`:
/// see `sim::verilog_file`).
pub fn verilated(name: &str) -> Arc<Verilated> {
    verilated_with(name, [])
}

/// Unit `name` with `params` over its defaults, Verilated (once per process:
/// `sim::verilated`).
pub fn verilated_with<const K: usize>(name: &str, params: [(&str, u64); K]) -> Arc<Verilated> {
    let (unit, params) = unit_params(name, params);
    sim::verilated(unit, &params, None).unwrap_or_else(|e| panic!("{e}"))
}

/// rust-hdl and Verilator in lockstep through a whole frame: every output of `raster_top`
/// compared every cycle.
impl<U: Block + Pins> frame::Cycle for Dual<U> {
    fn cycle(&mut self, d: &frame::Drive) -> Result<frame::Sense, String> {
        let pins = frame::named(d);
        Ok(frame::sense(&Dual::cycle(self, &streams::as_pins(&pins)).map_err(|m| m.to_string())?))
    }
}
