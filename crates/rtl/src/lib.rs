//! edgepaint hardware units in rust-hdl, one file per unit, and their Verilog emission.
//!
//! [`UNITS`] is the one table of units: each name, with its parameters, builds and emits
//! the unit (`hdl-out/<name>.v`, top module `<name>`); its model is `model::<name>` and its
//! tests are `testbenches/tests/<name>.rs`. [`DEFAULT_DESIGN`] is what `edgepaint` with no
//! arguments writes into `hdl-out/`.

pub mod emit;
pub mod ept;
pub mod se;
pub mod sim;

use emit::Emitted;
use std::collections::BTreeMap;

/// Parameter values of one unit by name, e.g. `{"P": 64}`.
pub type Params = BTreeMap<String, u64>;

/// One parameter of a unit.
#[derive(Debug)]
pub struct Param {
    pub name: &'static str,
    pub default: u64,
    /// What it means and which values are supported.
    pub doc: &'static str,
}

/// One hardware unit: its name, parameters and how to emit it.
pub struct Unit {
    pub name: &'static str,
    /// One line: what the unit is and which paper and figure it follows.
    pub doc: &'static str,
    pub params: &'static [Param],
    /// Emits the unit for complete, named parameters; `Err` for unsupported values.
    build: fn(&Params) -> Result<Emitted, String>,
}

/// Every unit, by name.
pub const UNITS: &[Unit] = &[
    Unit {
        name: "ept",
        doc: "edge painting tree, paper 002 Figs. 2-5: pixel i painted iff XL <= i <= XR",
        params: &[Param { name: "P", default: 64, doc: "pixels per scanline, a power of two from 8 to 1024" }],
        build: ept::emit_ept,
    },
    Unit {
        name: "se",
        doc: "shading engine, paper 000 Figs. 6-10: serial multipliers, bit-serial interpolator, EPT mask, z compare, 4 ports",
        params: &[
            Param { name: "P", default: 64, doc: "pixels per engine (region width): 8, 16, 32 or 64" },
            Param { name: "ZW", default: 24, doc: "bits of a z word (000: 24)" },
            Param { name: "CW", default: 16, doc: "bits of a colour word (000: 16)" },
            Param { name: "F", default: 16, doc: "fraction bits of the lines' A and B" },
            Param { name: "I", default: 0, doc: "engine index i: region [P i, P (i + 1)), P (i + 1) < 2048" },
        ],
        build: se::emit_se,
    },
];

/// The default design: units and parameters that `edgepaint` with no arguments emits.
pub const DEFAULT_DESIGN: &[(&str, &[(&str, u64)])] =
    &[("ept", &[("P", 64)]), ("se", &[("P", 64), ("ZW", 24), ("CW", 16), ("F", 16), ("I", 0)])];

impl Unit {
    /// The unit called `name`.
    pub fn named(name: &str) -> Option<&'static Unit> {
        UNITS.iter().find(|u| u.name == name)
    }

    /// `given` over the defaults; `Err` names an unknown parameter.
    pub fn params(&self, given: impl IntoIterator<Item = (String, u64)>) -> Result<Params, String> {
        let mut out: Params = self.params.iter().map(|p| (p.name.to_owned(), p.default)).collect();
        for (k, v) in given {
            if !out.contains_key(&k) {
                let known: Vec<_> = self.params.iter().map(|p| p.name).collect();
                return Err(format!("unit {} has no parameter {k} (it has: {})", self.name, known.join(", ")));
            }
            out.insert(k, v);
        }
        Ok(out)
    }

    /// Emits the unit with `params` (complete: see [`Unit::params`]).
    pub fn emit(&self, params: &Params) -> Result<Emitted, String> {
        (self.build)(params)
    }
}
