//! Simulating edgepaint's RTL, for the CLI (`render --engine rtl`) and the testbenches.
//!
//! * [`HdlSim`] steps a rust-hdl unit directly (`simulate`, as `rtl::sim::tick` does; not
//!   rust-hdl's threaded `Simulation`).
//! * [`VlSim`] runs a unit's emitted Verilog under Verilator, in-process; [`Verilated`]
//!   builds the model (cached by content under `<target>/verilator/`).
//! * [`frame`] draws whole frames through `raster_top` with the depth and colour buffers
//!   in Rust ([`memory`]); [`soc`] draws them through `gpu_top` from a vertex buffer, with
//!   the buffers behind its AXI4 masters and a host on its registers; [`textured`] through
//!   the textured `raster_top`, with a texture memory; [`streams`] moves the model's
//!   transactions to and from ports.
//!
//! A unit plugs in through `rtl::sim::Pins` (its pins by Verilog name, values as
//! [`Value`]s of any width, so >64-bit ports work) and `rtl::emit::ports` (the port list,
//! read off the rust-hdl struct). A clocked unit's clock is the port named `clock`.

pub mod frame;
pub mod memory;
pub mod se_frame;
pub mod soc;
pub mod streams;
pub mod textured;
pub mod verilator;

use rtl::emit::Emitted;
pub use rtl::emit::Port;
pub use rtl::sim::{Pins, PortDir, Value};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
pub use verilator::{check_verilator, target_dir, write_if_changed, PortId, Verilated, VlSim};

use rust_hdl::prelude::*;

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

/// Outputs of one cycle, by pin name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outputs(pub Vec<(String, Value)>);

impl Outputs {
    /// The value of output `pin`; panics on an unknown name.
    pub fn get(&self, pin: &str) -> &Value {
        self.0.iter().find(|(n, _)| n == pin).map(|(_, v)| v).unwrap_or_else(|| panic!("no output {pin}"))
    }
}

/// The committed `hdl-out/` of this checkout.
pub fn hdl_out() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../hdl-out")
}

/// Where `hdl-out/` holds `e`'s Verilog, when `e` is a unit of the default design at its
/// parameters and formats ([`committed_build`]).
fn committed(e: &Emitted) -> Option<PathBuf> {
    let class_formats = e.params.get("N").map(|&n| fx::Formats::for_n(n as u32));
    committed_build(e.unit, &e.params).filter(|_| e.formats == class_formats).map(|(file, _)| file)
}

/// The file and ports of `unit` at `params` (at its size class's formats) in `hdl-out/`,
/// when the default design holds it: its entry in `hdl-out/manifest.json` (the test
/// `hdl_out_is_fresh` keeps both current). The simulations verilate that file, and take
/// its ports from there rather than emitting the unit again (seconds of rust-hdl for a
/// `raster_top`, in every process that simulates it).
fn committed_build(unit: &str, params: &rtl::Params) -> Option<(PathBuf, Vec<Port>)> {
    static MANIFEST: std::sync::OnceLock<Option<serde_json::Value>> = std::sync::OnceLock::new();
    let manifest = MANIFEST
        .get_or_init(|| serde_json::from_str(&std::fs::read_to_string(hdl_out().join("manifest.json")).ok()?).ok())
        .as_ref()?;
    for entry in manifest["units"].as_array()? {
        let entry_params: Option<rtl::Params> = serde_json::from_value(entry["parameters"].clone()).ok();
        if entry["unit"] != unit || entry_params.as_ref() != Some(params) {
            continue;
        }
        let port = |p: &serde_json::Value| {
            let dir = match p["direction"].as_str()? {
                "input" => PortDir::In,
                "output" => PortDir::Out,
                _ => return None,
            };
            Some(Port { name: p["name"].as_str()?.to_string(), dir, width: p["width"].as_u64()? as usize })
        };
        let ports = entry["ports"].as_array()?.iter().map(port).collect::<Option<Vec<Port>>>()?;
        return Some((hdl_out().join(entry["file"].as_str()?), ports));
    }
    None
}

/// The Verilog file of `e` as the simulations should see it: the committed file in
/// `hdl-out/` when the default design holds this unit with these parameters (so the
/// committed file is what is simulated), otherwise `e` written under the target directory
/// (`<target>/hdl/<unit>-<params>[-F<formats>]/<unit>.v`, `<formats>` a hash of formats
/// other than the size class's defaults).
pub fn verilog_file(e: &Emitted) -> Result<PathBuf, String> {
    if let Some(file) = committed(e) {
        return Ok(file);
    }
    let mut tag: String = e.params.iter().map(|(k, v)| format!("-{k}{v}")).collect();
    let class = e.params.get("N").map(|&n| fx::Formats::for_n(n as u32));
    if let Some(f) = e.formats.filter(|f| Some(*f) != class) {
        // FNV-1a of the formats as written: stable across runs and builds.
        let text: String = f.named().iter().map(|(k, f)| format!("{k}={f};")).collect();
        let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ b as u64).wrapping_mul(0x100_0000_01b3));
        tag.push_str(&format!("-F{hash:016x}"));
    }
    write_if_changed(&target_dir().join("hdl").join(format!("{}{tag}", e.unit)), &e.file(), &e.verilog)
}

/// Verilates `e` (see [`verilog_file`] for which file).
pub fn verilate(e: &Emitted) -> Result<Verilated, String> {
    Verilated::new(e.unit, &verilog_file(e)?, &e.ports)
}

/// `unit` emitted with `params` at `formats` (`None`: its size class's defaults) and
/// Verilated, once per process for each parameters and formats: rust-hdl takes seconds to
/// emit `raster_top`, and the frame tests want it again and again. Threads asking for the
/// same model wait for the first to make it.
pub fn verilated(
    unit: &rtl::Unit,
    params: &rtl::Params,
    formats: Option<&fx::Formats>,
) -> Result<Arc<Verilated>, String> {
    type Models = BTreeMap<String, Arc<Mutex<Option<Arc<Verilated>>>>>;
    static MODELS: Mutex<Models> = Mutex::new(BTreeMap::new());
    let key = format!("{} {params:?} {formats:?}", unit.name);
    let slot = MODELS.lock().unwrap_or_else(|e| e.into_inner()).entry(key).or_default().clone();
    let mut model = slot.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(m) = model.as_ref() {
        return Ok(m.clone());
    }
    let class_formats = params.get("N").map(|&n| fx::Formats::for_n(n as u32));
    let committed = committed_build(unit.name, params).filter(|_| formats.is_none_or(|f| Some(*f) == class_formats));
    let m = Arc::new(match committed {
        Some((file, ports)) => Verilated::new(unit.name, &file, &ports)?,
        None => verilate(&match formats {
            Some(f) => unit.emit_at(params, f)?,
            None => unit.emit(params)?,
        })?,
    });
    *model = Some(m.clone());
    Ok(m)
}
