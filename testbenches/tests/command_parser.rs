//! The command parser (001 Fig. 4): rust-hdl and Verilator in lockstep with
//! `model::command_parser`, every output compared every cycle, reading vertex buffers from
//! `model::read_memory` (a latency, back-pressure) and handing triangles to a rasterizer
//! that takes them when it pleases: whole shipped scenes, buffers started one after
//! another, a small vertex cache, and every broken rule ending in the model's error code.

use fx::Build;
use model::command_parser::{CommandParser as Model, Inputs, Outputs as ModelOutputs, Params, State, ANY_SCREEN};
use model::read_memory::{ReadMemory, ReadResponse};
use model::vertex_buffer::{broken, Fault, VertexBuffer, RECORD_BYTES};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rtl::command_parser::{CommandParser, BEAT_BYTES};
use rust_hdl::prelude::Block;
use testbenches::stimulus::shipped_buffers;
use testbenches::streams::parsed;
use testbenches::{count, seed, verilated_with, Dual, Outputs, Pins, Value};

/// Where the buffers sit on the bus.
const BASE: u32 = 0x1000;

/// The memory and the rasterizer around a lockstep run.
#[derive(Clone, Copy)]
struct Pace {
    latency: u32,
    /// Chance that the memory holds back an address or a beat in a cycle.
    stall: f64,
    /// Chance that the rasterizer takes the output triangle in a cycle.
    take: f64,
    /// The largest screen the parser accepts (its `max_width`, `max_height`).
    screen: [u32; 2],
}

const AT_ONCE: Pace = Pace { latency: 0, stall: 0.0, take: 1.0, screen: ANY_SCREEN };

/// How one buffer ended, and the triangles the rasterizer took from it.
#[derive(Clone, Copy, Debug, PartialEq)]
struct End {
    fault: Option<Fault>,
    triangles: usize,
}

/// The model's state as the `state` port codes it.
fn code(s: State) -> u128 {
    match s {
        State::Init => 0,
        State::Header => 1,
        State::TriIndex => 2,
        State::VertexFetch => 3,
        State::CpReady => 4,
        State::End => 5,
        State::Error => 6,
    }
}

/// Every output of the parser against the model's: the state, the error code, the done
/// pulses, the render state, the read address and the output triangle (their words where
/// they are valid).
fn compare(got: &Outputs, o: &ModelOutputs) -> Result<(), String> {
    let mut want: Vec<(String, Value)> = vec![
        ("state".into(), Value::new(3, code(o.state))),
        ("fault".into(), Value::new(4, o.fault.map_or(0, |f| f as u128))),
        ("frame_done".into(), Value::new(1, o.frame_done as u128)),
        ("buffer_done".into(), Value::new(1, o.buffer_done as u128)),
        ("render_valid".into(), Value::new(1, o.render.is_some() as u128)),
        ("bus$ar_valid".into(), Value::new(1, o.ar.is_some() as u128)),
        ("bus$ar_size".into(), Value::new(3, BEAT_BYTES.trailing_zeros().into())),
        ("bus$ar_burst".into(), Value::new(2, 1)),
        ("bus$r_ready".into(), Value::new(1, 1)),
        ("out$valid".into(), Value::new(1, o.out.is_some() as u128)),
    ];
    if let Some(h) = o.render {
        let [r, g, b] = h.background.map(u128::from);
        want.extend([
            ("width".into(), Value::new(16, h.width.into())),
            ("height".into(), Value::new(16, h.height.into())),
            ("cull_back".into(), Value::new(1, h.cull_back as u128)),
            ("background".into(), Value::new(24, r | g << 8 | b << 16)),
        ]);
    }
    if let Some(q) = o.ar {
        want.push(("bus$ar_addr".into(), Value::new(32, q.addr.into())));
        want.push(("bus$ar_len".into(), Value::new(8, (q.beats - 1).into())));
    }
    if let Some(t) = o.out {
        want.extend(parsed("out", &t));
    }
    match want.iter().find(|(pin, v)| got.get(pin) != v) {
        Some((pin, v)) => Err(format!("{pin}: RTL {}, model {v}", got.get(pin))),
        None => Ok(()),
    }
}

/// The memory's side of the bus as pins.
fn bus_pins(r: &ReadResponse) -> [(&'static str, Value); 4] {
    [
        ("bus$ar_ready", Value::new(1, r.ar_ready as u128)),
        ("bus$r_valid", Value::new(1, r.r_valid as u128)),
        ("bus$r_data", Value::new(128, r.data_128())),
        ("bus$r_resp", Value::new(2, if r.r_error { 2 } else { 0 })),
    ]
}

/// `memory` at [`BASE`]; the buffers at `starts` (bus addresses) read one after another,
/// each started in the cycle after the one before ended (frame or buffer done, or an
/// error), `start` also raised at random while the parser is busy (it must be ignored).
/// The model and both simulators in lockstep; returns how each buffer ended.
fn lockstep<U: Block + Pins>(
    dual: &mut Dual<U>,
    cache: u32,
    memory: &[u8],
    starts: &[u32],
    pace: Pace,
    rng: &mut ChaCha8Rng,
    max_cycles: u64,
) -> Result<Vec<End>, String> {
    let build = Build::default();
    let mut model = Model::new(Params { beat_bytes: BEAT_BYTES, cache }, build)?;
    let (mut stall_rng, mut take_rng) = (ChaCha8Rng::seed_from_u64(rng.gen()), ChaCha8Rng::seed_from_u64(rng.gen()));
    let mut mem = ReadMemory::new(memory, BASE, BEAT_BYTES, pace.latency, move || stall_rng.gen_bool(pace.stall));
    let (mut ends, mut next, mut triangles) = (Vec::new(), 0, 0);
    let mut want_start = true;
    for cycle in 0..max_cycles {
        let o = model.outputs();
        let idle = matches!(o.state, State::Init | State::Error);
        let (start, address) = if want_start && next < starts.len() {
            (true, starts[next])
        } else {
            (!idle && rng.gen_bool(0.05), rng.gen())
        };
        let (screen, bus) = (pace.screen, mem.response());
        let i = Inputs { start, address, screen, bus, out_ready: take_rng.gen_bool(pace.take) };
        let mut pins = vec![
            ("start", Value::new(1, start as u128)),
            ("address", Value::new(32, address.into())),
            ("max_width", Value::new(16, screen[0].into())),
            ("max_height", Value::new(16, screen[1].into())),
            ("out$ready", Value::new(1, i.out_ready as u128)),
        ];
        pins.extend(bus_pins(&i.bus));
        let got = dual.cycle(&pins).map_err(|m| m.to_string())?;
        compare(&got, &o).map_err(|e| format!("cycle {cycle}, buffer {next}: {e}"))?;
        if o.out.is_some() && i.out_ready {
            triangles += 1;
        }
        if want_start && start {
            want_start = false;
            next += 1;
        } else if o.frame_done || o.buffer_done || (o.fault.is_some() && !want_start) {
            ends.push(End { fault: o.fault, triangles: std::mem::take(&mut triangles) });
            want_start = true;
            if ends.len() == starts.len() {
                return Ok(ends);
            }
        }
        mem.clock(o.ar, true);
        model.clock(&i);
    }
    Err(format!("{} of {} buffers ended in {max_cycles} cycles", ends.len(), starts.len()))
}

/// A parser with a vertex cache of `2^CB` entries beside its Verilog, both just out of
/// reset.
fn dual<const CB: usize, const G: usize>() -> Dual<CommandParser<CB, G>> {
    let vl = verilated_with("command_parser", [("CACHE", 1 << CB)]);
    Dual::new(CommandParser::<CB, G>::new(), vl.model().unwrap_or_else(|e| panic!("{e}")))
}

/// Every shipped scene at class 10 at latency 0, the rasterizer taking each triangle at
/// once; the scenes of up to 600 triangles also at latency 20, the memory stalling 30% of
/// the cycles and the rasterizer taking half (the rest too at every pace in the soak, with
/// `EDGEPAINT_N` of 10,000: rust-hdl steps the parser at about 10,000 cycles a second).
/// The same outputs as the model every cycle, every triangle handed over.
#[test]
fn command_parser_shipped_scenes_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let stalled = Pace { latency: 20, stall: 0.3, take: 0.5, ..AT_ONCE };
    for (name, vb) in shipped_buffers() {
        let bytes = vb.encode();
        let paces = if vb.triangles.len() <= 600 || count() >= 10_000 { vec![AT_ONCE, stalled] } else { vec![AT_ONCE] };
        for pace in paces {
            let ends = lockstep(&mut dual::<9, 32>(), 512, &bytes, &[BASE], pace, &mut rng, 5_000_000)
                .unwrap_or_else(|e| panic!("seed {seed}, {name}, latency {}: {e}", pace.latency));
            assert_eq!(ends, [End { fault: None, triangles: vb.triangles.len() }], "{name}");
        }
    }
}

/// Two buffers in one memory, read one after the other by a parser with 16 cache entries:
/// the second holds other vertices at the same indices, so an entry left from the first
/// would hand over a wrong vertex; then the first again. Shared vertices conflict in the
/// small cache all the time.
#[test]
fn command_parser_small_cache_and_buffers_back_to_back_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let scenes = shipped_buffers();
    let scene = |n: &str| &scenes.iter().find(|(name, _)| name.ends_with(n)).expect("a shipped scene").1;
    let (a, b) = (scene("sphere.json"), scene("torus.json"));
    let mut memory = a.encode();
    memory.resize(memory.len().next_multiple_of(RECORD_BYTES), 0);
    let second = BASE + memory.len() as u32;
    memory.extend(b.encode());
    let pace = Pace { latency: 3, stall: 0.2, take: 0.7, ..AT_ONCE };
    let ends = lockstep(&mut dual::<4, 1>(), 16, &memory, &[BASE, second, BASE], pace, &mut rng, 5_000_000)
        .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    let whole = |vb: &VertexBuffer| End { fault: None, triangles: vb.triangles.len() };
    assert_eq!(ends, [whole(a), whole(b), whole(a)]);
}

/// A triangle naming one vertex twice, V0 = V1, the first fetched: V1's lookup comes the
/// cycle after V0 is written into the cache, before the block RAM can read it back, and
/// hits the bypass register (the model finds it in the cache).
#[test]
fn command_parser_vertex_repeated_hits_the_entry_just_written() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    let fan = broken::fan();
    let mut bytes = fan.encode();
    let v0 = u32::from_le_bytes(bytes[fan.index_offset()..][..4].try_into().expect("a word"));
    broken::set(&mut bytes, fan.index_offset() + 4, v0);
    let ends = lockstep(&mut dual::<9, 32>(), 512, &bytes, &[BASE], AT_ONCE, &mut rng, 10_000)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(ends, [End { fault: None, triangles: fan.triangles.len() }]);
}

/// Every broken rule (`vertex_buffer::broken`), a buffer for another build, a buffer
/// address off a record boundary, a buffer longer than the memory (the read past it
/// answered with an error) and a screen wider or taller than `max_width` x `max_height`:
/// the parser stops with the model's error code, in both simulators, and a good buffer
/// started after the error is read whole.
#[test]
fn command_parser_broken_buffers_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let fan = broken::fan();
    let good = fan.encode();
    let whole = End { fault: None, triangles: fan.triangles.len() };
    let mut cases = broken::cases();
    let mut other = good.clone();
    broken::set(&mut other, 12, 11);
    cases.push(("a buffer for size class 11", other, Fault::Build));
    for (what, bytes, fault) in cases {
        let mut memory = bytes;
        let second = BASE + memory.len() as u32;
        memory.extend(&good);
        let ends = lockstep(&mut dual::<9, 32>(), 512, &memory, &[BASE, second], AT_ONCE, &mut rng, 10_000)
            .unwrap_or_else(|e| panic!("seed {seed}, {what}: {e}"));
        assert_eq!(ends, [End { fault: Some(fault), triangles: ends[0].triangles }, whole], "{what}");
    }
    let ends = lockstep(&mut dual::<9, 32>(), 512, &good, &[BASE + 16, BASE], AT_ONCE, &mut rng, 10_000)
        .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    assert_eq!(ends, [End { fault: Some(Fault::Address), triangles: 0 }, whole]);
    let short = &good[..good.len() - RECORD_BYTES];
    let ends = lockstep(&mut dual::<9, 32>(), 512, short, &[BASE], AT_ONCE, &mut rng, 10_000)
        .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    assert_eq!(ends, [End { fault: Some(Fault::Bus), triangles: ends[0].triangles }]);
    for (screen, fault) in [([15, 16], Some(Fault::Screen)), ([16, 15], Some(Fault::Screen)), ([16, 16], None)] {
        let pace = Pace { screen, ..AT_ONCE };
        let ends = lockstep(&mut dual::<9, 32>(), 512, &good, &[BASE], pace, &mut rng, 10_000)
            .unwrap_or_else(|e| panic!("seed {seed}, buffers of {screen:?}: {e}"));
        let triangles = if fault.is_some() { 0 } else { fan.triangles.len() };
        assert_eq!(ends, [End { fault, triangles }], "buffers of {screen:?}");
    }
}

/// Random edits of the fan's buffer (`EDGEPAINT_N` / 10 of them) at random latencies,
/// stalls and paces: the parser agrees with the model on every cycle until the buffer
/// ends, in an error code or a frame.
#[test]
fn command_parser_mutated_buffers_vs_model() {
    let seed = seed();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let good = broken::fan().encode();
    let mut faults = std::collections::BTreeSet::new();
    for case in 0..count() / 10 {
        let mut bytes = good.clone();
        broken::mutate(&mut bytes, &mut |n| rng.gen_range(0..n));
        let pace = Pace { latency: rng.gen_range(0..8), stall: 0.2, take: rng.gen_range(0.2..1.0), ..AT_ONCE };
        let ends = lockstep(&mut dual::<9, 32>(), 512, &bytes, &[BASE], pace, &mut rng, 20_000)
            .unwrap_or_else(|e| panic!("seed {seed}, case {case}: {e}"));
        faults.insert(ends[0].fault.map(|f| f as u8));
    }
    assert!(faults.len() >= 5, "the edits reach several rules: {faults:?}");
}

/// The emitted parser's ports: the AXI4 read master's and the triangle link's, named as
/// the README gives them; an unsupported cache size is refused by name.
#[test]
fn command_parser_ports() {
    let unit = rtl::Unit::named("command_parser").expect("a unit");
    let e = unit.emit(&unit.params([]).expect("defaults")).expect("emits");
    let names: Vec<&str> = e.ports.iter().map(|p| p.name.as_str()).collect();
    for pin in
        ["bus$ar_valid", "bus$ar_addr", "bus$ar_len", "bus$r_data", "bus$r_resp", "out$v2_iw", "out$end_of_frame"]
    {
        assert!(names.contains(&pin), "{pin} in {names:?}");
    }
    let mut p = unit.params([]).expect("defaults");
    p.insert("CACHE".into(), 100);
    assert!(unit.emit(&p).unwrap_err().contains("CACHE = 100"));
}
