//! Verilog emission: one file per unit, top module named after the unit, and the
//! `manifest.json` that lists every emitted unit with its parameters and ports.

use crate::sim::PortDir;
use crate::{Params, Unit, DEFAULT_DESIGN, DEFAULT_VARIANTS, UNITS};
use rust_hdl::prelude::*;
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One top-level port of an emitted unit, as Verilog sees it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub dir: PortDir,
    pub width: usize,
}

/// One unit, emitted with one set of parameters.
#[derive(Clone, Debug)]
pub struct Emitted {
    pub unit: &'static str,
    pub params: Params,
    /// The number formats it is built at (scanline units), recorded in the manifest.
    pub formats: Option<fx::Formats>,
    pub ports: Vec<Port>,
    pub verilog: String,
    /// The directory under the output directory that holds it: `None` for the output
    /// directory itself, a [`DEFAULT_VARIANTS`] entry's name for that build.
    pub dir: Option<String>,
}

impl Emitted {
    /// The file's path under the output directory ([`file_name`]).
    pub fn file(&self) -> String {
        file_name(self.unit, self.dir.as_deref())
    }
}

/// A unit's file under an output directory: `<unit>.v`, or `<dir>/<unit>.v`.
pub fn file_name(unit: &str, dir: Option<&str>) -> String {
    match dir {
        Some(dir) => format!("{dir}/{unit}.v"),
        None => format!("{unit}.v"),
    }
}

/// Emits `u` with `name` as its top module (rust-hdl's `generate_verilog` would call it
/// `top`), after rust-hdl's checks for open inputs, loops and writes to inputs.
pub fn verilog<U: Block>(name: &str, u: &U) -> String {
    check_all(u).unwrap_or_else(|e| panic!("rust-hdl checks failed for {name}: {e:?}"));
    let mut defs = ModuleDefines::default();
    u.accept(name, &mut defs);
    defs.defines()
}

/// Builds `U`, connects it and emits it as unit `name` with its ports.
pub fn emit<U: Block + Default>(name: &'static str, params: Params) -> Emitted {
    emit_unit(name, U::default(), &params)
}

/// Connects `u` and emits it as unit `name` with `params` and its ports.
pub fn emit_unit<U: Block>(name: &'static str, mut u: U, params: &Params) -> Emitted {
    u.connect_all();
    Emitted {
        unit: name,
        params: params.clone(),
        formats: None,
        ports: ports(&u),
        verilog: verilog(name, &u),
        dir: None,
    }
}

/// The top-level ports of `u`, in declaration order (a bundle's pins are named
/// `<bundle>$<pin>`, as rust-hdl flattens them).
pub fn ports<U: Block>(u: &U) -> Vec<Port> {
    #[derive(Default)]
    struct PortProbe {
        depth: usize,
        namespace: Vec<String>,
        ports: Vec<Port>,
    }
    impl Probe for PortProbe {
        fn visit_start_scope(&mut self, _name: &str, _node: &dyn Block) {
            self.depth += 1;
        }
        fn visit_start_namespace(&mut self, name: &str, _node: &dyn Block) {
            if self.depth == 1 {
                self.namespace.push(name.to_owned());
            }
        }
        fn visit_atom(&mut self, name: &str, signal: &dyn Atom) {
            let dir = match signal.kind() {
                AtomKind::InputParameter => PortDir::In,
                AtomKind::OutputParameter => PortDir::Out,
                _ => return,
            };
            if self.depth == 1 {
                let name = self.namespace.iter().map(String::as_str).chain([name]).collect::<Vec<_>>().join("$");
                self.ports.push(Port { name, dir, width: signal.bits() });
            }
        }
        fn visit_end_namespace(&mut self, _name: &str, _node: &dyn Block) {
            if self.depth == 1 {
                self.namespace.pop();
            }
        }
        fn visit_end_scope(&mut self, _name: &str, _node: &dyn Block) {
            self.depth -= 1;
        }
    }
    let mut probe = PortProbe::default();
    u.accept("top", &mut probe);
    probe.ports
}

/// `manifest.json`: per unit its name, parameters, file and ports.
pub fn manifest(units: &[Emitted]) -> String {
    #[derive(Serialize)]
    struct Manifest<'a> {
        units: Vec<ManifestUnit<'a>>,
    }
    #[derive(Serialize)]
    struct ManifestUnit<'a> {
        unit: &'a str,
        parameters: &'a Params,
        #[serde(skip_serializing_if = "Option::is_none")]
        formats: Option<BTreeMap<&'static str, String>>,
        file: String,
        ports: Vec<ManifestPort<'a>>,
    }
    #[derive(Serialize)]
    struct ManifestPort<'a> {
        name: &'a str,
        direction: &'static str,
        width: usize,
    }
    let units = units
        .iter()
        .map(|e| ManifestUnit {
            unit: e.unit,
            parameters: &e.params,
            formats: e.formats.map(|f| f.named().iter().map(|(k, f)| (*k, f.to_string())).collect()),
            file: e.file(),
            ports: e
                .ports
                .iter()
                .map(|p| ManifestPort { name: &p.name, direction: p.dir.verilog(), width: p.width })
                .collect(),
        })
        .collect();
    let mut text = serde_json::to_string_pretty(&Manifest { units }).expect("JSON of plain values");
    text.push('\n');
    text
}

/// Every file of a design: each unit's Verilog, then `manifest.json`.
pub fn files(units: &[Emitted]) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = units.iter().map(|e| (e.file(), e.verilog.clone())).collect();
    out.push(("manifest.json".into(), manifest(units)));
    out
}

/// A unit of the default design: the unit, its parameters (every one of them), and the
/// directory under `hdl-out/` that holds it (`None`: `hdl-out/` itself).
pub struct DesignEntry {
    pub unit: &'static Unit,
    pub params: Params,
    pub dir: Option<String>,
}

/// The default design's units: [`DEFAULT_DESIGN`], then [`DEFAULT_VARIANTS`], each in the
/// directory `<unit>-<NAME>=<VALUE>-...` of the parameters it sets.
pub fn default_entries() -> Vec<DesignEntry> {
    let entry = |name: &str, params: &[(&str, u64)], dir: Option<String>| {
        let unit = Unit::named(name).expect("DEFAULT_DESIGN names units in UNITS");
        let params =
            unit.params(params.iter().map(|(k, v)| (k.to_string(), *v))).expect("DEFAULT_DESIGN parameters are valid");
        DesignEntry { unit, params, dir }
    };
    let main = DEFAULT_DESIGN.iter().map(|(name, params)| entry(name, params, None));
    let variants = DEFAULT_VARIANTS.iter().map(|(name, set)| {
        let (_, base) = DEFAULT_DESIGN.iter().find(|(n, _)| n == name).expect("a variant of a DEFAULT_DESIGN unit");
        let params: Vec<(&str, u64)> = base.iter().chain(set.iter()).copied().collect();
        let dir = set.iter().fold(name.to_string(), |d, (k, v)| format!("{d}-{k}={v}"));
        entry(name, &params, Some(dir))
    });
    main.chain(variants).collect()
}

/// The default design ([`default_entries`]), emitted.
pub fn default_design() -> Vec<Emitted> {
    default_entries()
        .into_iter()
        .map(|d| Emitted { dir: d.dir, ..d.unit.emit(&d.params).expect("DEFAULT_DESIGN parameters are supported") })
        .collect()
}

/// Writes `files(units)` into `dir` (created if missing); returns the paths written.
pub fn write(dir: &Path, units: &[Emitted]) -> std::io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)?;
    files(units)
        .into_iter()
        .map(|(name, text)| {
            let path = dir.join(name);
            std::fs::create_dir_all(path.parent().expect("a file under dir"))?;
            std::fs::write(&path, text)?;
            Ok(path)
        })
        .collect()
}

/// Names of every unit in `UNITS`, for messages.
pub fn unit_names() -> String {
    UNITS.iter().map(|u| u.name).collect::<Vec<_>>().join(", ")
}

/// A timing wrapper for place and route of `e` (not part of the design): module
/// `<unit>_pnr` with four pins, `clk`, `sin`, `load`, `sout`. The unit's inputs come from
/// a shift chain fed by `sin` and its outputs go into registers, so every path through the
/// unit is timed register to register; the output registers load into a second shift
/// chain that leaves on `sout`, so every output is observable and synthesis keeps all of
/// the unit. A unit's `clock` port gets `clk`.
pub fn pnr_wrapper(e: &Emitted) -> String {
    let (ins, outs): (Vec<&Port>, Vec<&Port>) =
        e.ports.iter().filter(|p| p.name != "clock").partition(|p| p.dir == PortDir::In);
    let iw: usize = ins.iter().map(|p| p.width).sum();
    let ow: usize = outs.iter().map(|p| p.width).sum();
    assert!(iw > 0 && ow > 0, "{} needs inputs and outputs to be placed and routed", e.unit);
    let mut conns = Vec::new();
    let mut at = 0;
    for p in &ins {
        conns.push(format!("        .{}(chain_in[{}:{}])", p.name, at + p.width - 1, at));
        at += p.width;
    }
    at = 0;
    for p in &outs {
        conns.push(format!("        .{}(out_d[{}:{}])", p.name, at + p.width - 1, at));
        at += p.width;
    }
    if e.ports.iter().any(|p| p.name == "clock") {
        conns.push("        .clock(clk)".into());
    }
    let shift = |reg: &str, w: usize, input: &str| {
        if w == 1 {
            input.to_owned()
        } else {
            format!("{{{reg}[{}:0], {input}}}", w - 2)
        }
    };
    format!(
        "// Place-and-route timing wrapper for `{unit}`, written by `edgepaint report`; not part of\n\
         // the design. Inputs arrive through a shift chain (registers), outputs are registered and\n\
         // leave through a loadable shift chain, so every path through `{unit}` is timed register\n\
         // to register and no output can be optimised away.\n\
         module {unit}_pnr(clk, sin, load, sout);\n\
         \x20   input wire clk;\n\
         \x20   input wire sin;\n\
         \x20   input wire load;\n\
         \x20   output wire sout;\n\
         \x20   reg [{im}:0] chain_in;\n\
         \x20   wire [{om}:0] out_d;\n\
         \x20   reg [{om}:0] out_q;\n\
         \x20   reg [{om}:0] chain_out;\n\
         \x20   {unit} dut(\n{conns}\n    );\n\
         \x20   always @(posedge clk) begin\n\
         \x20       chain_in <= {shift_in};\n\
         \x20       out_q <= out_d;\n\
         \x20       chain_out <= load ? out_q : {shift_out};\n\
         \x20   end\n\
         \x20   assign sout = chain_out[{om}];\n\
         endmodule\n",
        unit = e.unit,
        im = iw - 1,
        om = ow - 1,
        conns = conns.join(",\n"),
        shift_in = shift("chain_in", iw, "sin"),
        shift_out = shift("chain_out", ow, "1'b0"),
    )
}
