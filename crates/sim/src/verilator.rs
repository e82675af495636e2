//! Emitted Verilog under Verilator, in-process.
//!
//! [`Verilated::new`] builds a shared library of the Verilated model with a small C++
//! shim (`extern "C"`: new, eval, delete, and one setter and one getter that take a port
//! by its index) and [`Verilated::model`] loads it. The library is cached under
//! `<target>/verilator/<top>-<hash>/`, the hash taken over the Verilog text, the top
//! module, the ports, the shim and Verilator's version: a model is rebuilt only when one
//! of those changes (a fresh clone or a touched file rebuilds nothing that is cached).
//! Verilator's runtime (`libverilated.a`, the same for every model built with the same
//! flags) is compiled once, under `<target>/verilator/runtime-<hash>/`, and linked into
//! each model, which then compiles only its own classes. Threads and processes that want
//! the same model (or the runtime) wait for the first to build it (a mutex within a
//! process, a lock file beside the model across processes); a build works in a directory
//! of its own and renames the result into place.
//!
//! [`VlSim`] moves port values as [`Value`]s by name (the dual-simulation tests) or by
//! [`PortId`] with plain integers (frame simulation, a million cycles per second and
//! more), resolving the shim's symbols once when the model is loaded.

use crate::{Port, PortDir, Sim, Value};
use libloading::Library;
use std::collections::{BTreeMap, HashMap};
use std::ffi::c_void;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

/// What to do when Verilator is missing or unusable.
const SETUP_HINT: &str =
    "run scripts/setup-tools.sh, then `source scripts/tools-env.sh` (it puts the pinned Verilator's wrapper on PATH)";

/// Verilator warnings waived while building a model. WIDTH: rust-hdl writes every literal
/// and index as 32 bits (`xl[32'h5]`), so widths never match.
const IGNORED_WARNINGS: &[&str] = &["WIDTH"];

/// Bumped whenever the shim or the build commands change, so cached models are rebuilt.
const SHIM_VERSION: u32 = 3;

/// The flags every model and the runtime are Verilated and compiled with: the runtime
/// built once serves every model only because they agree. `OPT_SLOW=-O0`: a large model's
/// `__Slow` files (construction and the initial settle, run once) unoptimised, which halves
/// their compile time (raster_top's: 4.1 s at Verilator's default -Os, 2.0 s at -O0) and
/// leaves the code run every cycle as fast as before. `-fno-semantic-interposition`: the
/// model's calls between its own functions go straight to them rather than through the
/// shared library's symbol table (raster_top's frame simulation on the dense scene 787k
/// and 801k cycles/s against 743k and 764k without, stop 63).
const VERILATOR_FLAGS: &[&str] = &[
    "--cc",
    "-sv",
    "--build",
    "-CFLAGS",
    "-fPIC",
    "-CFLAGS",
    "-fno-semantic-interposition",
    "-MAKEFLAGS",
    "OPT_SLOW=-O0",
];

/// The environment variable that sets the C++ optimisation of a model's code run every cycle
/// (Verilator's `OPT_FAST`), [`MODEL_OPT`] when unset. The test command sets -O1
/// (`scripts/test-build-env.sh`): raster_top's model then compiles in 3.9 s rather than 5.8
/// and simulates at about half the speed, which its tests, most of them in rust-hdl's far
/// slower simulator too, do not notice.
const MODEL_OPT_VAR: &str = "EDGEPAINT_MODEL_OPT";

/// The per-cycle code's optimisation when [`MODEL_OPT_VAR`] is unset (`render --engine
/// rtl`, the benches): -O2, under which raster_top's model steps about twice as fast as at
/// Verilator's own default, -Os (README, "Frame simulation").
const MODEL_OPT: &str = "-O2";

/// The optimisation [`MODEL_OPT_VAR`] asks for (`value`: the variable's value).
fn model_opt(value: Option<&str>) -> Result<&str, String> {
    match value {
        None | Some("") => Ok(MODEL_OPT),
        Some(o @ ("-O0" | "-O1" | "-O2" | "-O3" | "-Os")) => Ok(o),
        Some(o) => Err(format!("{MODEL_OPT_VAR} is {o:?}: it takes -O0, -O1, -O2, -O3 or -Os (or unset: {MODEL_OPT})")),
    }
}

/// Where edgepaint keeps what it builds to simulate (emitted Verilog, Verilated models):
/// the Cargo target directory this binary was built in, so artifacts follow
/// `CARGO_TARGET_DIR` (the nearest ancestor holding `CACHEDIR.TAG` or `.rustc_info.json`:
/// Cargo writes the tag only when it creates the directory itself, so a `target/` made
/// beforehand has only the second); for a binary outside one (installed),
/// `$XDG_CACHE_HOME/edgepaint`, else `~/.cache/edgepaint`, else the temporary directory's.
pub fn target_dir() -> PathBuf {
    work_dir(std::env::current_exe().ok().as_deref(), |name| std::env::var_os(name))
}

/// [`target_dir`] for the binary `exe`, with the environment variable `var`.
fn work_dir(exe: Option<&Path>, var: impl Fn(&str) -> Option<std::ffi::OsString>) -> PathBuf {
    let cargo = |d: &&Path| d.join("CACHEDIR.TAG").is_file() || d.join(".rustc_info.json").is_file();
    if let Some(dir) = exe.and_then(|exe| exe.ancestors().find(cargo)) {
        return dir.to_path_buf();
    }
    let var = |name| var(name).filter(|v| !v.is_empty()).map(PathBuf::from);
    let cache = var("XDG_CACHE_HOME").or_else(|| var("HOME").map(|h| h.join(".cache")));
    cache.unwrap_or_else(std::env::temp_dir).join("edgepaint")
}

/// Checks that `exe` runs and is Verilator 5; returns its version line. The error says
/// how to install it.
pub fn check_verilator(exe: &str) -> Result<String, String> {
    match Command::new(exe).arg("--version").output() {
        Ok(o) if String::from_utf8_lossy(&o.stdout).starts_with("Verilator 5.") => {
            Ok(String::from_utf8_lossy(&o.stdout).trim().to_owned())
        }
        Ok(o) => Err(format!(
            "`{exe} --version` printed {:?}, not \"Verilator 5.x\": {SETUP_HINT}",
            String::from_utf8_lossy(&o.stdout).trim()
        )),
        Err(e) => Err(format!("Verilator ({exe}) is not installed ({e}): {SETUP_HINT}")),
    }
}

/// Writes `text` to `dir/name` unless it already holds exactly that; returns the path.
/// The file is replaced by a rename, so a reader in another thread never sees it half
/// written.
pub fn write_if_changed(dir: &Path, name: &str, text: &str) -> Result<PathBuf, String> {
    let path = dir.join(name);
    if std::fs::read_to_string(&path).ok().as_deref() != Some(text) {
        std::fs::create_dir_all(dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
        static WRITES: AtomicU64 = AtomicU64::new(0);
        let n = WRITES.fetch_add(1, Ordering::Relaxed);
        let tmp = dir.join(format!(".{name}.{}.{n}", std::process::id()));
        std::fs::write(&tmp, text).map_err(|e| format!("writing {}: {e}", tmp.display()))?;
        std::fs::rename(&tmp, &path).map_err(|e| format!("renaming {} to {}: {e}", tmp.display(), path.display()))?;
    }
    Ok(path)
}

/// A port's name as a member of Verilator's model class: `$` (rust-hdl's bundle
/// separator) escaped as Verilator escapes it.
fn member(port: &str) -> String {
    port.replace('$', "__024")
}

/// The C++ shim of model `V<top>` with `ports`: ports are numbered in the order given.
fn shim(top: &str, ports: &[Port]) -> String {
    let mut set = String::new();
    let mut get = String::new();
    for (i, p) in ports.iter().enumerate() {
        let m = member(&p.name);
        if p.width <= 64 {
            if p.dir == PortDir::In {
                set.push_str(&format!("    case {i}: t->{m} = w[0]; break;\n"));
            }
            get.push_str(&format!("    case {i}: w[0] = t->{m}; break;\n"));
        } else {
            let n = p.width.div_ceil(32);
            if p.dir == PortDir::In {
                set.push_str(&format!(
                    "    case {i}: for (int k = 0; k < {n}; ++k) t->{m}[k] = (uint32_t)(w[k / 2] >> (32 * (k % 2))); break;\n"
                ));
            }
            get.push_str(&format!(
                "    case {i}: for (int k = 0; k < {n}; ++k) w[k / 2] |= (uint64_t)t->{m}[k] << (32 * (k % 2)); break;\n"
            ));
        }
    }
    format!(
        "// The C ABI of V{top} for edgepaint's sim crate (sim::verilator), written with the model.\n\
         #include <cstdint>\n\
         #include \"verilated.h\"\n\
         #include \"V{top}.h\"\n\
         extern \"C\" {{\n\
         void* ep_new() {{ return new V{top}; }}\n\
         void ep_delete(void* m) {{ delete static_cast<V{top}*>(m); }}\n\
         void ep_eval(void* m) {{ static_cast<V{top}*>(m)->eval(); }}\n\
         void ep_set(void* m, uint32_t port, const uint64_t* w) {{\n\
         \x20   V{top}* t = static_cast<V{top}*>(m);\n\
         \x20   switch (port) {{\n{set}    }}\n\
         }}\n\
         void ep_get(void* m, uint32_t port, uint64_t* w) {{\n\
         \x20   V{top}* t = static_cast<V{top}*>(m);\n\
         \x20   switch (port) {{\n{get}    }}\n\
         }}\n\
         }}\n"
    )
}

/// A Verilated model, built (or found in the cache) and loaded, ready to instantiate.
pub struct Verilated {
    unit: String,
    ports: Vec<Port>,
    library: Arc<Library>,
}

impl Verilated {
    /// Builds the model of `file` (top module `unit`, with the given ports), or reuses the
    /// cached build of the same Verilog. Fails, saying how to install it, when Verilator
    /// is not on PATH, and with Verilator's or the compiler's messages when they fail.
    pub fn new(unit: &str, file: &Path, ports: &[Port]) -> Result<Self, String> {
        let version = check_verilator("verilator")?;
        let verilog = std::fs::read_to_string(file).map_err(|e| format!("reading {}: {e}", file.display()))?;
        let shim = shim(unit, ports);
        let opt_var = std::env::var(MODEL_OPT_VAR).ok();
        let opt = model_opt(opt_var.as_deref())?;
        let key = (&version, unit, &verilog, &shim, opt);
        let dir = target_dir().join("verilator").join(format!("{unit}-{:016x}", hash(&key)));
        let lib = dir.join(format!("libV{unit}.so"));
        once(&lib, || {
            let runtime = runtime(&version)?;
            build(unit, file, &shim, opt, &runtime, &dir, &lib)
        })?;
        // SAFETY: the library is the model just built from our own shim; loading it runs
        // only Verilator's static initialisers.
        let library = unsafe { Library::new(&lib) }.map_err(|e| format!("loading {}: {e}", lib.display()))?;
        Ok(Verilated { unit: unit.to_owned(), ports: ports.to_vec(), library: Arc::new(library) })
    }

    /// A fresh instance of the model, every input zero.
    pub fn model(&self) -> Result<VlSim, String> {
        let sym = |name: &str| format!("{}: symbol {name} of the model's library", self.unit);
        // SAFETY: the signatures are those of the shim written by `shim` above.
        unsafe {
            let new =
                *self.library.get::<extern "C" fn() -> *mut c_void>(b"ep_new").map_err(|e| sym(&e.to_string()))?;
            let api = Api {
                delete: *self.library.get(b"ep_delete").map_err(|e| sym(&e.to_string()))?,
                eval: *self.library.get(b"ep_eval").map_err(|e| sym(&e.to_string()))?,
                set: *self.library.get(b"ep_set").map_err(|e| sym(&e.to_string()))?,
                get: *self.library.get(b"ep_get").map_err(|e| sym(&e.to_string()))?,
            };
            let handle = new();
            if handle.is_null() {
                return Err(format!("{}: the model could not be created", self.unit));
            }
            let index = self.ports.iter().enumerate().map(|(i, p)| (p.name.clone(), PortId(i as u32))).collect();
            Ok(VlSim {
                _library: self.library.clone(),
                api,
                handle,
                unit: self.unit.clone(),
                ports: self.ports.clone(),
                index,
                words: Vec::new(),
                driven: vec![None; self.ports.len()],
            })
        }
    }
}

/// Runs `cmd`; its output in the error when it fails.
fn run(cmd: &mut Command, what: &str) -> Result<(), String> {
    let out = cmd.output().map_err(|e| format!("{what}: cannot run {:?}: {e}; {SETUP_HINT}", cmd.get_program()))?;
    if out.status.success() {
        return Ok(());
    }
    Err(format!(
        "{what} failed ({}):\n{}{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    ))
}

/// A hash of `key` and [`SHIM_VERSION`], naming a cache directory.
fn hash(key: &impl Hash) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    (SHIM_VERSION, VERILATOR_FLAGS, key).hash(&mut h);
    h.finish()
}

/// Runs `make` unless `file` exists; while one thread of any process makes a file, the
/// others wanting the same file wait for it: the threads of this process on a mutex, other
/// processes (the CLI's tests run several `render --engine rtl` at once) on an exclusive
/// lock of `<file>.lock`, so a model is compiled once, not once per process.
fn once(file: &Path, make: impl FnOnce() -> Result<(), String>) -> Result<(), String> {
    static MAKING: Mutex<BTreeMap<PathBuf, Arc<Mutex<()>>>> = Mutex::new(BTreeMap::new());
    let slot = MAKING.lock().unwrap_or_else(|e| e.into_inner()).entry(file.to_path_buf()).or_default().clone();
    let _making = slot.lock().unwrap_or_else(|e| e.into_inner());
    if file.is_file() {
        return Ok(());
    }
    let dir = file.parent().expect("a file in a directory");
    std::fs::create_dir_all(dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
    let lock_path = file.with_extension("lock");
    let lock = std::fs::File::create(&lock_path).map_err(|e| format!("creating {}: {e}", lock_path.display()))?;
    lock.lock().map_err(|e| format!("locking {}: {e}", lock_path.display()))?;
    if file.is_file() {
        return Ok(());
    }
    make()
}

/// A fresh directory of this thread's own beside `dir`, for a build to publish into
/// `dir` by renaming.
fn work_dir_beside(dir: &Path) -> Result<PathBuf, String> {
    static BUILDS: AtomicU64 = AtomicU64::new(0);
    let n = BUILDS.fetch_add(1, Ordering::Relaxed);
    let work = dir.with_extension(format!("build-{}-{n}", std::process::id()));
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).map_err(|e| format!("creating {}: {e}", work.display()))?;
    Ok(work)
}

/// Moves `built` to `to`, creating `to`'s directory, and removes the work directory `work`.
fn publish(built: &Path, to: &Path, work: &Path) -> Result<(), String> {
    let dir = to.parent().expect("a file in a directory");
    std::fs::create_dir_all(dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
    std::fs::rename(built, to).map_err(|e| format!("moving {} to {}: {e}", built.display(), to.display()))?;
    let _ = std::fs::remove_dir_all(work);
    Ok(())
}

/// `verilator` with [`VERILATOR_FLAGS`] and the waivers, building make target `target`
/// in `work`.
fn verilator(work: &Path, target: &str) -> Command {
    let jobs = std::thread::available_parallelism().map_or(2, |n| n.get());
    let mut cmd = Command::new("verilator");
    cmd.args(VERILATOR_FLAGS)
        .args(["-j", &jobs.to_string(), "-MAKEFLAGS", target])
        .args(IGNORED_WARNINGS.iter().map(|w| format!("-Wno-{w}")))
        .arg("--Mdir")
        .arg(work);
    cmd
}

/// Verilator's runtime library, `libverilated.a`, compiled once per Verilator version (from
/// an empty module, with the models' flags) and returned from the cache after that.
fn runtime(version: &str) -> Result<PathBuf, String> {
    let lib = target_dir().join("verilator").join(format!("runtime-{:016x}", hash(&version))).join("libverilated.a");
    once(&lib, || {
        let work = work_dir_beside(lib.parent().expect("in a directory"))?;
        let stub = work.join("ep_runtime.v");
        std::fs::write(&stub, "module ep_runtime;\nendmodule\n")
            .map_err(|e| format!("writing {}: {e}", stub.display()))?;
        run(verilator(&work, "libverilated.a").args(["--top-module", "ep_runtime"]).arg(&stub), "Verilator's runtime")?;
        publish(&work.join("libverilated.a"), &lib, &work)
    })?;
    Ok(lib)
}

/// Verilates `file` with `shim` in a directory of this thread's own, compiling only the
/// model's classes (its per-cycle code at optimisation `opt`),
/// links them with the `runtime` into a shared library and renames it to `lib` (in `dir`).
fn build(unit: &str, file: &Path, shim: &str, opt: &str, runtime: &Path, dir: &Path, lib: &Path) -> Result<(), String> {
    let work = work_dir_beside(dir)?;
    let shim_file = work.join("shim.cpp");
    std::fs::write(&shim_file, shim).map_err(|e| format!("writing {}: {e}", shim_file.display()))?;
    let archive = format!("libV{unit}.a");
    let mut verilator = verilator(&work, &archive);
    verilator.args(["-MAKEFLAGS", &format!("OPT_FAST={opt}")]);
    verilator.args(["--top-module", unit]).arg(file).arg(&shim_file);
    run(&mut verilator, &format!("Verilating {}", file.display()))?;
    let linked = work.join(format!("libV{unit}.so"));
    let mut link = Command::new("c++");
    link.args(["-shared", "-fPIC", "-o"])
        .arg(&linked)
        .arg("-Wl,--whole-archive")
        .arg(work.join(archive))
        .arg(runtime)
        .args(["-Wl,--no-whole-archive", "-pthread"]);
    run(&mut link, &format!("linking the model of {}", file.display()))?;
    publish(&linked, lib, &work)
}

/// The shim's functions.
struct Api {
    delete: extern "C" fn(*mut c_void),
    eval: extern "C" fn(*mut c_void),
    set: extern "C" fn(*mut c_void, u32, *const u64),
    get: extern "C" fn(*mut c_void, u32, *mut u64),
}

/// A port of a [`VlSim`], looked up once by name ([`VlSim::port`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PortId(u32);

/// One instance of a Verilated unit.
pub struct VlSim {
    /// Keeps the library loaded while the instance lives.
    _library: Arc<Library>,
    api: Api,
    handle: *mut c_void,
    unit: String,
    ports: Vec<Port>,
    index: HashMap<String, PortId>,
    words: Vec<u64>,
    /// The words last driven on each input (none yet: `None`), so that driving an input
    /// with the value it holds costs no call into the model (a frame's harness drives
    /// every input every cycle, most of them unchanged: 13% of a frame's time before).
    driven: Vec<Option<Vec<u64>>>,
}

impl Drop for VlSim {
    fn drop(&mut self) {
        (self.api.delete)(self.handle);
    }
}

impl VlSim {
    /// The top module's name.
    pub fn unit(&self) -> &str {
        &self.unit
    }

    /// The ports it was built with.
    pub fn ports(&self) -> &[Port] {
        &self.ports
    }

    /// Port `name`; panics if the unit has none.
    pub fn port(&self, name: &str) -> PortId {
        *self.index.get(name).unwrap_or_else(|| panic!("{} has no port {name}", self.unit))
    }

    /// Drives input `id` (at most 64 bits wide) with the low bits of `v`.
    pub fn set_u64(&mut self, id: PortId, v: u64) {
        let p = &self.ports[id.0 as usize];
        debug_assert!(p.dir == PortDir::In && p.width <= 64, "{}: {} is not a narrow input", self.unit, p.name);
        let masked = if p.width == 64 { v } else { v & ((1 << p.width) - 1) };
        self.drive(id, &[masked]);
    }

    /// Drives input `id` (65 to 128 bits wide) with the low bits of `v`.
    pub fn set_u128(&mut self, id: PortId, v: u128) {
        let p = &self.ports[id.0 as usize];
        debug_assert!(p.dir == PortDir::In && (65..=128).contains(&p.width), "{}: {}", self.unit, p.name);
        let masked = if p.width == 128 { v } else { v & ((1 << p.width) - 1) };
        self.drive(id, &[masked as u64, (masked >> 64) as u64]);
    }

    /// Drives input `id` with the little-endian words `words` (as many as its width needs).
    pub fn set_words(&mut self, id: PortId, words: &[u64]) {
        let p = &self.ports[id.0 as usize];
        assert!(p.dir == PortDir::In && words.len() == p.width.div_ceil(64), "{}: {}", self.unit, p.name);
        self.drive(id, words);
    }

    /// Drives input `id` with `words` (as many as its width needs) unless it holds them.
    fn drive(&mut self, id: PortId, words: &[u64]) {
        let slot = &mut self.driven[id.0 as usize];
        if slot.as_deref() == Some(words) {
            return;
        }
        (self.api.set)(self.handle, id.0, words.as_ptr());
        match slot {
            Some(held) => held.copy_from_slice(words),
            None => *slot = Some(words.to_vec()),
        }
    }

    /// Reads port `id` into `words` (as many as its width needs), little-endian.
    pub fn get_words(&mut self, id: PortId, words: &mut [u64]) {
        assert_eq!(words.len(), self.ports[id.0 as usize].width.div_ceil(64), "{}", self.unit);
        // The shim ORs a wide port's 32-bit words in.
        words.fill(0);
        (self.api.get)(self.handle, id.0, words.as_mut_ptr());
    }

    /// The width of port `id`.
    pub fn width(&self, id: PortId) -> usize {
        self.ports[id.0 as usize].width
    }

    /// Reads port `id` (at most 64 bits wide).
    pub fn get_u64(&mut self, id: PortId) -> u64 {
        debug_assert!(self.ports[id.0 as usize].width <= 64);
        let mut w = 0;
        (self.api.get)(self.handle, id.0, &mut w);
        w
    }

    /// Propagates the inputs.
    pub fn eval(&mut self) {
        (self.api.eval)(self.handle);
    }

    fn checked(&self, pin: &str, dir: PortDir) -> (PortId, usize) {
        let id = self.port(pin);
        let p = &self.ports[id.0 as usize];
        assert!(dir == PortDir::Out || p.dir == PortDir::In, "{}: {pin} is an output", self.unit);
        (id, p.width)
    }
}

impl Sim for VlSim {
    fn name(&self) -> &'static str {
        "verilator"
    }

    fn set(&mut self, pin: &str, value: &Value) {
        let (id, width) = self.checked(pin, PortDir::In);
        assert_eq!(value.width(), width, "{}: {pin} is {width} bits wide", self.unit);
        self.drive(id, value.words());
    }

    fn settle(&mut self) {
        self.eval();
    }

    fn clock(&mut self) {
        let clock = self.port("clock");
        for level in [1, 0] {
            self.set_u64(clock, level);
            self.eval();
        }
    }

    fn get(&mut self, pin: &str) -> Value {
        let (id, width) = self.checked(pin, PortDir::Out);
        self.words.clear();
        self.words.resize(width.div_ceil(64).max(1), 0);
        (self.api.get)(self.handle, id.0, self.words.as_mut_ptr());
        Value::from_words(width, &self.words)
    }
}

#[cfg(test)]
mod tests {
    use super::{model_opt, once, work_dir};
    use std::ffi::OsString;
    use std::path::{Path, PathBuf};

    /// A binary under `<root>/target/release/` (made here, with `marker` in `target/`), and
    /// the root, removed when dropped.
    fn tree(marker: Option<&str>) -> (PathBuf, PathBuf, tempfile::TempDir) {
        let root = tempfile::tempdir().unwrap();
        let target = root.path().join("target");
        std::fs::create_dir_all(target.join("release")).unwrap();
        if let Some(m) = marker {
            std::fs::write(target.join(m), "").unwrap();
        }
        (target.clone(), target.join("release").join("edgepaint"), root)
    }

    /// EDGEPAINT_MODEL_OPT: unset or empty is -O2; a level is passed on; anything else is an
    /// error naming the variable and what it takes.
    #[test]
    fn model_opt_takes_a_level_or_nothing() {
        assert_eq!(model_opt(None), Ok("-O2"));
        assert_eq!(model_opt(Some("")), Ok("-O2"));
        assert_eq!(model_opt(Some("-O1")), Ok("-O1"));
        assert_eq!(model_opt(Some("-Os")), Ok("-Os"));
        for bad in ["O1", "-O1 -march=native", "-Ofast", "fast"] {
            let e = model_opt(Some(bad)).unwrap_err();
            assert!(e.contains("EDGEPAINT_MODEL_OPT") && e.contains(bad) && e.contains("-O1"), "{e}");
        }
    }

    fn env<'a>(vars: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<OsString> + 'a {
        move |name| vars.iter().find(|(k, _)| *k == name).map(|(_, v)| OsString::from(v))
    }

    #[test]
    fn work_dir_is_the_cargo_target_directory_tagged_or_not() {
        for marker in ["CACHEDIR.TAG", ".rustc_info.json"] {
            let (target, exe, _root) = tree(Some(marker));
            assert_eq!(work_dir(Some(&exe), env(&[("HOME", "/home/u")])), target, "{marker}");
        }
    }

    #[test]
    fn work_dir_outside_a_target_directory_is_the_user_cache() {
        let (_, exe, _root) = tree(None);
        let home = [("HOME", "/home/u")];
        assert_eq!(work_dir(Some(&exe), env(&home)), Path::new("/home/u/.cache/edgepaint"));
        let xdg = [("HOME", "/home/u"), ("XDG_CACHE_HOME", "/var/cache/u")];
        assert_eq!(work_dir(Some(&exe), env(&xdg)), Path::new("/var/cache/u/edgepaint"));
        assert_eq!(work_dir(None, env(&[])), std::env::temp_dir().join("edgepaint"));
    }

    /// A build another process holds (its lock on `<file>.lock`: a lock of another open
    /// file, as another process's would be) is waited for, and not made again once it is
    /// published.
    #[test]
    fn once_waits_for_a_build_in_another_process() {
        let root = tempfile::tempdir().unwrap();
        let file = root.path().join("model").join("libVunit.so");
        std::fs::create_dir_all(file.parent().unwrap()).unwrap();
        let other = std::fs::File::create(file.with_extension("lock")).unwrap();
        other.lock().unwrap();
        let waiter = {
            let file = file.clone();
            std::thread::spawn(move || {
                let mut made = false;
                once(&file, || {
                    made = true;
                    Ok(())
                })
                .unwrap();
                made
            })
        };
        std::thread::sleep(std::time::Duration::from_millis(200));
        assert!(!waiter.is_finished(), "once went on while the other process held the lock");
        std::fs::write(&file, "built").unwrap();
        other.unlock().unwrap();
        assert!(!waiter.join().unwrap(), "the file the other process published was made again");
        let mut made = false;
        once(&root.path().join("other").join("lib.so"), || {
            made = true;
            Ok(())
        })
        .unwrap();
        assert!(made, "a file nobody has made is made");
    }
}
