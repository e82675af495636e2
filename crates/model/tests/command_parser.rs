//! The command parser's model (001 Fig. 4): the triangles it hands over against the
//! buffer as `vertex_buffer::decode` reads it, its cycles derived by hand, its vertex
//! fetches on indexed and unindexed meshes, and every broken rule ending in its error code
//! within bounded cycles, reading nothing outside the buffer.

use fx::Build;
use model::command_parser::{run, Bench, Outcome, Params, Run, Triangle};
use model::vertex_buffer::{broken, pack, Fault, IndexRecord, VertexBuffer, VertexRecord, HEADER_BYTES, RECORD_BYTES};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use scene::{Trilist, Vertex};

fn seed() -> u64 {
    std::env::var("EDGEPAINT_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1)
}

fn cases() -> usize {
    std::env::var("EDGEPAINT_N").ok().and_then(|s| s.parse().ok()).unwrap_or(1000)
}

/// The triangles of `vb` as the parser must hand them over, with TI's flags.
fn expected(vb: &VertexBuffer) -> Vec<Triangle> {
    vb.triangles
        .iter()
        .map(|t| Triangle { vertices: vb.triangle(t), end_of_buffer: t.end_of_buffer, end_of_frame: t.end_of_frame })
        .collect()
}

fn handed_over(r: &Run) -> Vec<Triangle> {
    r.triangles.iter().map(|&(_, t)| t).collect()
}

/// Every read of `r` inside `[base, base + length)`.
fn reads_inside(r: &Run, base: u32, length: u64, beat_bytes: u32) -> bool {
    r.reads.iter().all(|q| {
        let end = u64::from(q.addr) + u64::from(q.beats * beat_bytes);
        q.addr >= base && end <= u64::from(base) + length
    })
}

/// Two triangles sharing two vertices, on a 64-bit bus at latency 0, every triangle taken
/// at once. By the timing of `model::command_parser`: start in cycle 0; the header's
/// address offered in 1, its 12 beats in 2-13, checked in 14; index record 0 offered in 15,
/// beats 16-19, checked in 20, when record 1 is asked for ahead: offered in 21, beats
/// 22-25, checked in 26 (V0's lookup waits for the bus); V0, V1, V2 miss: each a lookup, an
/// address, 4 beats and a check (27-33, 34-40, 41-47), and in 47 triangle 0 goes to the
/// output register and record 1, read ahead, becomes the current one; triangle 0 is taken
/// in 48; two hits (48, 49), one miss (50-56), triangle 1 out in 56, taken in 57,
/// `frame_done` in 58: the same end as reading record 1 after triangle 0.
#[test]
fn two_triangles_cycle_by_cycle() {
    let v = |x: i128, y: i128| VertexRecord { x: x << 4, y: y << 4, z: 100, c: [10, 20, 30] };
    let one = 1 << 15;
    let vb = VertexBuffer {
        build: Build::default(),
        width: 64,
        height: 64,
        cull_back: false,
        background: [0; 3],
        triangles: vec![
            IndexRecord { v: [0, 1, 2], iw: [one; 3], end_of_buffer: false, end_of_frame: false },
            IndexRecord { v: [2, 1, 3], iw: [one; 3], end_of_buffer: true, end_of_frame: true },
        ],
        vertices: vec![v(1, 1), v(30, 2), v(3, 30), v(40, 40)],
    };
    let bus64 = Params { beat_bytes: 8, ..Params::default() };
    let r = run(bus64, Build::default(), &vb.encode(), Bench::default()).expect("parameters");
    assert_eq!(r.outcome, Outcome::FrameDone);
    let taken: Vec<u64> = r.triangles.iter().map(|t| t.0).collect();
    assert_eq!(taken, [48, 57]);
    assert_eq!(r.cycles, 58);
    assert_eq!(handed_over(&r), expected(&vb));
    assert_eq!((r.stats.index_bursts, r.stats.vertex_bursts, r.stats.cache_hits), (2, 4, 2));
    let addrs: Vec<u32> = r.reads.iter().map(|q| q.addr - 0x1000).collect();
    let rec = |n: usize| (HEADER_BYTES + n * RECORD_BYTES) as u32;
    // Header; index 0; index 1 ahead; vertices 0, 1, 2; vertex 3.
    assert_eq!(addrs, [0, rec(0), rec(1), rec(2), rec(3), rec(4), rec(5)]);
}

/// Shipped scenes, packed, through the parser at latency 0 and 20 with the memory and the
/// rasterizer stalling at random: the triangles are the buffer's, in order, with its
/// flags, and every read is inside the buffer.
#[test]
fn shipped_scenes_come_out_as_the_buffer_holds_them() {
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    for path in scene::shipped::all().expect("scenes/") {
        let list = scene::Scene::load(&path).and_then(|s| s.to_trilist()).expect("a shipped scene");
        let build = Build::for_screen(list.width, list.height);
        let (vb, _) = pack(&list, &build, true, [0; 3]).expect("packs");
        let bytes = vb.encode();
        for (latency, params) in [(0, Params::default()), (20, Params { beat_bytes: 4, cache: 8 })] {
            let (mut a, mut b) = (ChaCha8Rng::seed_from_u64(rng.gen()), ChaCha8Rng::seed_from_u64(rng.gen()));
            let bench = Bench {
                latency,
                stall: Box::new(move || a.gen_bool(0.3)),
                take: Box::new(move |_| b.gen_bool(0.5)),
                ..Bench::default()
            };
            let r = run(params, build, &bytes, bench).expect("parameters");
            let what = format!("{}, latency {latency}, {params:?}", path.display());
            assert_eq!(r.outcome, Outcome::FrameDone, "{what}");
            assert!(handed_over(&r) == expected(&vb), "{what}: the triangles differ from the buffer's");
            assert!(reads_inside(&r, 0x1000, bytes.len() as u64, params.beat_bytes), "{what}");
            assert_eq!(r.reads_outside, 0, "{what}");
        }
    }
}

/// The torus of `n` x `n` quads, as an index-ordered mesh, and the same triangles with no
/// vertex shared (a soup): vertex fetches per triangle with the default cache.
#[test]
fn vertex_fetches_per_triangle_indexed_and_soup() {
    let n = 24;
    let at = |i: usize, j: usize| {
        let (x, y) = (4.0 + 200.0 * (i % n) as f64 / n as f64, 4.0 + 200.0 * (j % n) as f64 / n as f64);
        Vertex::new(x + (j % n) as f64 * 0.25, y, 0.5, [(i * 10 % 256) as f64, (j * 10 % 256) as f64, 90.0])
    };
    let mut triangles = Vec::new();
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    let list = Trilist { width: 256, height: 256, triangles, textures: Vec::new() };
    let build = Build::for_screen(256, 256);
    let (vb, _) = pack(&list, &build, false, [0; 3]).expect("packs");
    let r = run(Params::default(), build, &vb.encode(), Bench::default()).expect("parameters");
    assert_eq!(r.outcome, Outcome::FrameDone);
    let indexed = r.stats.fetches_per_triangle();
    assert!(indexed <= 1.2, "index-ordered grid: {indexed} fetches per triangle");
    // The soup: every triangle's own three vertices.
    let mut soup = vb.clone();
    soup.vertices.clear();
    for t in &mut soup.triangles {
        for k in 0..3 {
            soup.vertices.push(vb.vertices[t.v[k] as usize]);
            t.v[k] = soup.vertices.len() as u32 - 1;
        }
    }
    let r = run(Params::default(), build, &soup.encode(), Bench::default()).expect("parameters");
    assert_eq!(r.outcome, Outcome::FrameDone);
    assert_eq!(r.stats.fetches_per_triangle(), 3.0);
    assert_eq!(handed_over(&r), expected(&soup));
}

/// The dense torus (76,500 triangles in rows of 255 vertices): the default cache holds a
/// row, so each vertex is fetched about once (0.5 per triangle); 32 entries do not, and
/// each vertex is fetched again a row later (about 2).
#[test]
fn the_default_vertex_cache_holds_a_row_of_the_dense_torus() {
    let path = scene::shipped::dense();
    let list = scene::Scene::load(&path).and_then(|s| s.to_trilist()).expect("the dense scene");
    let build = Build::for_screen(list.width, list.height);
    let (vb, _) = pack(&list, &build, true, [0; 3]).expect("packs");
    let bytes = vb.encode();
    let fetches = |cache| {
        let bench = Bench { max_cycles: 10_000_000, ..Bench::default() };
        let r = run(Params { cache, ..Params::default() }, build, &bytes, bench).expect("parameters");
        assert_eq!(r.outcome, Outcome::FrameDone);
        assert_eq!(r.stats.triangles as usize, vb.triangles.len());
        r.stats.fetches_per_triangle()
    };
    let (default, small) = (fetches(Params::default().cache), fetches(32));
    assert!(default <= 0.55, "{default} fetches per triangle at the default cache");
    assert!(small > 1.8, "{small} fetches per triangle at 32 entries");
}

/// Each class of broken rule stops the parser with its code within 200 cycles, every read
/// inside the buffer; so do a buffer for another build, off a record boundary, longer than
/// the memory, and a screen larger than the `screen` input.
#[test]
fn broken_buffers_stop_with_their_error_code() {
    let vb = broken::fan();
    let (build, good) = (vb.build, vb.encode());
    for (what, bytes, fault) in broken::cases() {
        let r = run(Params::default(), build, &bytes, Bench::default()).expect("parameters");
        assert_eq!(r.outcome, Outcome::Fault(fault), "{what}");
        assert!(r.cycles < 200, "{what}: {} cycles", r.cycles);
        assert!(reads_inside(&r, 0x1000, bytes.len() as u64, 8), "{what}");
    }
    // Another build's buffer; a buffer off a record boundary; a buffer longer than the
    // memory holds (the read past it answered with an error).
    let other = Build::for_screen(2048, 2048);
    let r = run(Params::default(), other, &good, Bench::default()).expect("parameters");
    assert_eq!(r.outcome, Outcome::Fault(Fault::Build));
    let r = run(Params::default(), build, &good, Bench { base: 0x1010, ..Bench::default() }).expect("parameters");
    assert_eq!((r.outcome, r.reads.len()), (Outcome::Fault(Fault::Address), 0));
    let r = run(Params::default(), build, &good[..good.len() - RECORD_BYTES], Bench::default()).expect("parameters");
    assert_eq!(r.outcome, Outcome::Fault(Fault::Bus));
    assert!(r.reads_outside > 0);
    // The fan's 16 x 16 screen on buffers one pixel narrower, or one row shorter, is
    // refused after the header, before any other read; on buffers of exactly 16 x 16 it
    // draws.
    for (screen, outcome) in [
        ([15, 16], Outcome::Fault(Fault::Screen)),
        ([16, 15], Outcome::Fault(Fault::Screen)),
        ([16, 16], Outcome::FrameDone),
    ] {
        let r = run(Params::default(), build, &good, Bench { screen, ..Bench::default() }).expect("parameters");
        assert_eq!(r.outcome, outcome, "buffers of {screen:?}");
        if r.outcome != Outcome::FrameDone {
            assert_eq!((r.reads.len(), r.triangles.len()), (1, 0), "only the header read");
        }
    }
}

/// Random edits of the fan's buffer, at random latencies and stalls: the parser always
/// ends (frame or buffer done, or an error code) within 5,000 cycles, reads only inside the
/// length its header gives, and hands over exactly the buffer's triangles, ending as its
/// last record says, whenever the buffer reads back.
#[test]
fn mutated_buffers_always_end_and_read_inside() {
    let vb = broken::fan();
    let good = vb.encode();
    let mut rng = ChaCha8Rng::seed_from_u64(seed());
    for case in 0..cases() {
        let mut bytes = good.clone();
        broken::mutate(&mut bytes, &mut |n| rng.gen_range(0..n));
        let (latency, pace) = (rng.gen_range(0..8), rng.gen_range(0.2..1.0));
        let (mut a, mut c) = (ChaCha8Rng::seed_from_u64(rng.gen()), ChaCha8Rng::seed_from_u64(rng.gen()));
        let bench = Bench {
            latency,
            stall: Box::new(move || a.gen_bool(0.2)),
            take: Box::new(move |_| c.gen_bool(pace)),
            max_cycles: 5000,
            ..Bench::default()
        };
        let r = run(Params::default(), vb.build, &bytes, bench).expect("parameters");
        assert_ne!(r.outcome, Outcome::Timeout, "case {case}");
        let length = u32::from_le_bytes(bytes[32..36].try_into().expect("a word"));
        assert!(reads_inside(&r, 0x1000, u64::from(length).max(HEADER_BYTES as u64), 8), "case {case}: {:?}", r.reads);
        if r.reads_outside > 0 {
            assert_eq!(r.outcome, Outcome::Fault(Fault::Bus), "case {case}");
        }
        if let Ok(back) = VertexBuffer::decode(&bytes) {
            if back.build == vb.build {
                // An edit may clear the last record's end of frame and keep its end of buffer:
                // the frame goes on in another buffer.
                let frame_ends = back.triangles.last().is_none_or(|t| t.end_of_frame);
                let outcome = if frame_ends { Outcome::FrameDone } else { Outcome::BufferDone };
                assert_eq!(r.outcome, outcome, "case {case}");
                assert!(handed_over(&r) == expected(&back), "case {case}");
            }
        }
    }
}
