//! Emitted Verilog under Verilator, in-process: marlin builds a shared library of the
//! Verilated model under `<target>/verilator/` (rebuilt only when the Verilog file is newer)
//! and loads it; ports are read and written through its C ABI.

use crate::{Port, PortDir, Sim, Value};
use marlin::verilator::dynamic::{AsDynamicVerilatedModel, DynamicVerilatedModel, VerilatorValue};
use marlin::verilator::{PortDirection, VerilatedModelConfig, VerilatorRuntime, VerilatorRuntimeOptions};
use rtl::emit::Emitted;
use std::path::{Path, PathBuf};
use std::process::Command;

/// What to do when Verilator is missing or unusable.
const SETUP_HINT: &str =
    "run scripts/setup-tools.sh, then `source scripts/tools-env.sh` (it puts the pinned Verilator's wrapper on PATH)";

/// Warnings Verilator would otherwise treat as errors while building a model. WIDTH:
/// rust-hdl writes every literal and index as 32 bits (`xl[32'h5]`), so widths never match.
pub(crate) const IGNORED_WARNINGS: &[&str] = &["WIDTH"];

/// The Cargo target directory this test or example binary was built in (the nearest
/// ancestor holding `CACHEDIR.TAG`), so artifacts follow `CARGO_TARGET_DIR`.
pub fn target_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("path of the running binary");
    exe.ancestors()
        .find(|d| d.join("CACHEDIR.TAG").is_file())
        .unwrap_or_else(|| panic!("{} is not inside a Cargo target directory", exe.display()))
        .to_path_buf()
}

/// Serialises model builds (see [`Verilated::model`]).
static BUILD: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// One Verilog file ready to be Verilated: the runtime that builds and owns its models.
pub struct Verilated {
    runtime: VerilatorRuntime,
    unit: String,
    file: PathBuf,
    ports: Vec<Port>,
}

impl Verilated {
    /// `file`, with top module `unit` and the given ports. Fails, saying how to install
    /// it, when Verilator is not on PATH.
    pub fn new(unit: &str, file: &Path, ports: &[Port]) -> Result<Self, String> {
        check_verilator("verilator")?;
        let artifacts = target_dir().join("verilator");
        std::fs::create_dir_all(&artifacts).map_err(|e| format!("creating {}: {e}", artifacts.display()))?;
        let runtime =
            VerilatorRuntime::new2(&artifacts, &[file], &[] as &[&Path], [], VerilatorRuntimeOptions::default())
                .map_err(|e| format!("Verilator runtime for {}: {e:?}; {SETUP_HINT}", file.display()))?;
        Ok(Verilated { runtime, unit: unit.to_owned(), file: file.to_owned(), ports: ports.to_vec() })
    }

    /// Writes `e`'s Verilog to `<target>/hdl/<unit>-<params>[-F<formats>]/<unit>.v` (only
    /// when it changed, so the model is not rebuilt; `<formats>` a hash of formats other
    /// than the size class's defaults) and prepares it.
    pub fn emitted(e: &Emitted) -> Result<Self, String> {
        let mut tag: String = e.params.iter().map(|(k, v)| format!("-{k}{v}")).collect();
        let class = e.params.get("N").map(|&n| fx::Formats::for_n(n as u32));
        if let Some(f) = e.formats.filter(|f| Some(*f) != class) {
            // FNV-1a of the formats as written: stable across runs and builds.
            let text: String = f.named().iter().map(|(k, f)| format!("{k}={f};")).collect();
            let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ b as u64).wrapping_mul(0x100_0000_01b3));
            tag.push_str(&format!("-F{hash:016x}"));
        }
        let file = write_if_changed(&target_dir().join("hdl").join(format!("{}{tag}", e.unit)), &e.file(), &e.verilog)?;
        Self::new(e.unit, &file, &e.ports)
    }

    /// The Verilog of `e` as the tests should see it: the committed `hdl-out/<unit>.v`
    /// when the default design holds this unit with these parameters (so the committed
    /// file is what is simulated), otherwise `e` written under the target directory.
    pub fn of(e: &Emitted) -> Result<Self, String> {
        let committed = |d: &Emitted| d.unit == e.unit && d.params == e.params && d.formats == e.formats;
        match rtl::emit::default_design().into_iter().find(committed) {
            Some(d) => Self::new(d.unit, &crate::hdl_out().join(d.file()), &d.ports),
            None => Self::emitted(e),
        }
    }

    /// The Verilog file.
    pub fn file(&self) -> &Path {
        &self.file
    }

    /// Builds the model (or reuses the last build) and instantiates it.
    pub fn model(&self) -> Result<VlSim<'_>, String> {
        let widths: Vec<(&str, usize, usize, PortDirection)> = self
            .ports
            .iter()
            .map(|p| {
                (
                    p.name.as_str(),
                    p.width - 1,
                    0,
                    if p.dir == PortDir::In { PortDirection::Input } else { PortDirection::Output },
                )
            })
            .collect();
        let config = VerilatedModelConfig {
            ignored_warnings: IGNORED_WARNINGS.iter().map(|w| w.to_string()).collect(),
            ..Default::default()
        };
        let file = self.file.to_str().ok_or_else(|| format!("{} is not UTF-8", self.file.display()))?;
        // One build at a time in this process: two tests building the same new model at
        // once have left marlin's build directory without its library.
        let _one_build = BUILD.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        let model = self
            .runtime
            .create_dyn_model(&self.unit, file, &widths, config)
            .map_err(|e| format!("Verilating {}: {e:?}", self.file.display()))?;
        Ok(VlSim { model, unit: self.unit.clone(), ports: self.ports.clone() })
    }
}

/// Checks that `exe` runs and is Verilator 5 (marlin needs 5.025 or later, and parses
/// `--version`); the error says how to install it.
pub fn check_verilator(exe: &str) -> Result<(), String> {
    match Command::new(exe).arg("--version").output() {
        Ok(o) if String::from_utf8_lossy(&o.stdout).starts_with("Verilator 5.") => Ok(()),
        Ok(o) => Err(format!(
            "`{exe} --version` printed {:?}, not \"Verilator 5.x\": {SETUP_HINT}",
            String::from_utf8_lossy(&o.stdout).trim()
        )),
        Err(e) => Err(format!("Verilator ({exe}) is not installed ({e}): {SETUP_HINT}")),
    }
}

/// Writes `text` to `dir/name` unless it already holds exactly that; returns the path.
/// The file is replaced by a rename, so a test Verilating it in another thread never
/// reads it half written.
pub fn write_if_changed(dir: &Path, name: &str, text: &str) -> Result<PathBuf, String> {
    let path = dir.join(name);
    if std::fs::read_to_string(&path).ok().as_deref() != Some(text) {
        std::fs::create_dir_all(dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
        let tmp = dir.join(format!(".{name}.{}.{:?}", std::process::id(), std::thread::current().id()));
        std::fs::write(&tmp, text).map_err(|e| format!("writing {}: {e}", tmp.display()))?;
        std::fs::rename(&tmp, &path).map_err(|e| format!("renaming {} to {}: {e}", tmp.display(), path.display()))?;
    }
    Ok(path)
}

/// A Verilated unit.
pub struct VlSim<'rt> {
    model: DynamicVerilatedModel<'rt>,
    unit: String,
    ports: Vec<Port>,
}

impl VlSim<'_> {
    /// The top module's name.
    pub fn unit(&self) -> &str {
        &self.unit
    }

    /// The ports it was built with.
    pub fn ports(&self) -> Vec<Port> {
        self.ports.clone()
    }

    fn width(&self, pin: &str) -> usize {
        self.ports.iter().find(|p| p.name == pin).unwrap_or_else(|| panic!("{} has no port {pin}", self.unit)).width
    }
}

impl Sim for VlSim<'_> {
    fn name(&self) -> &'static str {
        "verilator"
    }

    fn set(&mut self, pin: &str, value: &Value) {
        let width = self.width(pin);
        assert_eq!(value.width(), width, "{}: {pin} is {width} bits wide", self.unit);
        let w = value.words()[0];
        let result = match width {
            0..=8 => self.model.pin(pin, w as u8),
            9..=16 => self.model.pin(pin, w as u16),
            17..=32 => self.model.pin(pin, w as u32),
            33..=64 => self.model.pin(pin, w),
            _ => {
                let words: Vec<u32> = value
                    .words()
                    .iter()
                    .flat_map(|w| [*w as u32, (*w >> 32) as u32])
                    .take(width.div_ceil(32))
                    .collect();
                // SAFETY: marlin's `pin` for a wide port memcpy's the words into the model
                // before it returns and keeps no reference; `words` outlives that call. The
                // `'rt` lifetime it asks for is only what its signature can express.
                let words: &[u32] = unsafe { std::slice::from_raw_parts(words.as_ptr(), words.len()) };
                self.model.pin(pin, VerilatorValue::WDataInP(words))
            }
        };
        result.unwrap_or_else(|e| panic!("{}: setting {pin}: {e}", self.unit));
    }

    fn settle(&mut self) {
        self.model.eval();
    }

    fn clock(&mut self) {
        for level in [1u8, 0] {
            self.model.pin("clock", level).unwrap_or_else(|e| panic!("{}: clock: {e}", self.unit));
            self.model.eval();
        }
    }

    fn get(&mut self, pin: &str) -> Value {
        let width = self.width(pin);
        let v = self.model.read(pin).unwrap_or_else(|e| panic!("{}: reading {pin}: {e}", self.unit));
        match v {
            VerilatorValue::CData(x) => Value::new(width, x as u128),
            VerilatorValue::SData(x) => Value::new(width, x as u128),
            VerilatorValue::IData(x) => Value::new(width, x as u128),
            VerilatorValue::QData(x) => Value::new(width, x as u128),
            VerilatorValue::WDataOutP(words) => {
                let words: Vec<u64> =
                    words.chunks(2).map(|c| c[0] as u64 | c.get(1).map_or(0, |h| (*h as u64) << 32)).collect();
                Value::from_words(width, &words)
            }
            VerilatorValue::WDataInP(_) => unreachable!("marlin reads outputs as WDataOutP"),
        }
    }
}
