//! Flow control for the tests of valid/ready units: when a source offers its next item,
//! when a sink stalls, and one clock of a unit in either simulator arrangement.
//!
//! A source, once it offers an item, keeps it offered until the unit takes it (valid may
//! not drop before ready); a sink stalls for random periods: ready drops with probability
//! `stall` per cycle and comes back with probability `resume`.

use crate::{HdlSim, Outputs, Pins, Sim, Value};
use rand::Rng;
use rust_hdl::prelude::Block;

/// Flow control of one run: the chance that the source idles in a cycle, and that a ready
/// sink stalls from the next cycle or a stalled one resumes.
#[derive(Clone, Copy, Debug)]
pub struct Flow {
    pub idle: f64,
    pub stall: f64,
    pub resume: f64,
}

impl Flow {
    /// Items offered every cycle, the sink always ready.
    pub const BACK_TO_BACK: Flow = Flow { idle: 0.0, stall: 0.0, resume: 1.0 };
    /// Gaps between items and stalls of the sink, a few cycles long on average.
    pub const STALLING: Flow = Flow { idle: 0.25, stall: 0.15, resume: 0.3 };

    /// Whether the source offers an item this cycle, given whether it already does.
    pub fn offer(&self, offering: bool, rng: &mut impl Rng) -> bool {
        offering || !rng.gen_bool(self.idle)
    }

    /// The sink's ready in the next cycle, given this cycle's.
    pub fn next_ready(&self, ready: bool, rng: &mut impl Rng) -> bool {
        if ready {
            !rng.gen_bool(self.stall)
        } else {
            rng.gen_bool(self.resume)
        }
    }
}

/// One clock of a unit under test: drive the inputs given (others keep their values),
/// return every output before the clock edge. `Dual::cycle` for both simulators in
/// lockstep, [`hdl_cycle`] for rust-hdl's alone.
pub type Cycle<'a> = dyn FnMut(&[(&str, Value)]) -> Result<Outputs, String> + 'a;

/// One clock of `sim` alone (rust-hdl's simulator): the inputs, a settle, `outputs` read,
/// the clock edge.
pub fn hdl_cycle<U: Block + Pins>(sim: &mut HdlSim<U>, outputs: &[String], inputs: &[(&str, Value)]) -> Outputs {
    for (pin, v) in inputs {
        sim.set(pin, v);
    }
    sim.settle();
    let out = Outputs(outputs.iter().map(|p| (p.clone(), sim.get(p))).collect());
    sim.clock();
    out
}

/// The output ports of `u`, by name.
pub fn outputs<U: Block>(u: &U) -> Vec<String> {
    rtl::emit::ports(u).into_iter().filter(|p| p.dir == crate::PortDir::Out).map(|p| p.name).collect()
}
