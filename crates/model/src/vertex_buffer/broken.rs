//! Broken vertex buffers, one for each rule the command parser checks, and random edits:
//! what its tests, in the model (`model/tests/command_parser.rs`) and in the RTL
//! (`testbenches`), feed it and expect an error code from.

use super::{pack, Fault, VertexBuffer, HEADER_BYTES, RECORD_BYTES};
use fx::Build;
use scene::{Trilist, Vertex};

/// A fan of four triangles around a centre packed for a 16 x 16 screen (5 vertices): the
/// buffer the cases break.
pub fn fan() -> VertexBuffer {
    let v = |(x, y, z): (f64, f64, f64)| Vertex::new(x, y, z, [200.0, 100.0, 50.0]);
    let c = (8.0, 8.0, 0.5);
    let rim = [(1.0, 1.0, 0.2), (15.0, 1.0, 0.3), (15.0, 15.0, 0.4), (1.0, 15.0, 0.6)];
    let triangles = (0..4).map(|i| [v(c), v(rim[i]), v(rim[(i + 1) % 4])]).collect();
    let list = Trilist { width: 16, height: 16, triangles, textures: Vec::new() };
    pack(&list, &Build::for_screen(16, 16), true, [1, 2, 3]).expect("the fan packs").0
}

/// Writes little-endian word `w` at byte `at`.
pub fn set(bytes: &mut [u8], at: usize, w: u32) {
    bytes[at..at + 4].copy_from_slice(&w.to_le_bytes());
}

/// The fan's buffer broken in one rule each: what was broken, the bytes, the error code.
pub fn cases() -> Vec<(&'static str, Vec<u8>, Fault)> {
    let good = fan().encode();
    let tri = |t: usize| HEADER_BYTES + t * RECORD_BYTES;
    let vtx = |v: usize| HEADER_BYTES + 4 * RECORD_BYTES + v * RECORD_BYTES;
    type Edit = Box<dyn Fn(&mut Vec<u8>)>;
    let edits: Vec<(&'static str, Edit, Fault)> = vec![
        ("the magic", Box::new(|b| b[0] = b'X'), Fault::Magic),
        ("the version", Box::new(|b| b[4] = 2), Fault::Version),
        ("a flag", Box::new(|b| b[6] = 4), Fault::Reserved),
        ("T past the length", Box::new(|b| set(b, 16, 1000)), Fault::Layout),
        ("the index list inside the header", Box::new(|b| set(b, 24, 100)), Fault::Layout),
        ("a format word", Box::new(|b| set(b, 40, 0xff_ffff)), Fault::Build),
        ("V1 past the vertices", Box::new(move |b| set(b, tri(1) + 4, 5)), Fault::Index),
        ("a texture index", Box::new(move |b| set(b, tri(2) + 12, 7)), Fault::TriangleInfo),
        ("no end of buffer", Box::new(move |b| set(b, tri(3) + 12, 0xffff)), Fault::TriangleInfo),
        ("no inv_w of 1", Box::new(move |b| (0..3).for_each(|k| set(b, tri(2) + 16 + 4 * k, 1 << 14))), Fault::InvW),
        ("z outside its format", Box::new(move |b| set(b, vtx(1) + 8, 0x7fff_ffff)), Fault::VertexWord),
        ("a vertex's reserved word", Box::new(move |b| set(b, vtx(0) + 28, 9)), Fault::Reserved),
    ];
    edits
        .into_iter()
        .map(|(what, edit, fault)| {
            let mut bytes = good.clone();
            edit(&mut bytes);
            (what, bytes, fault)
        })
        .collect()
}

/// One to three random edits of `bytes`: a bit flipped, a byte replaced, or a word set to
/// a small number (an index, a count or an offset near the real ones). `below(n)` is a
/// random number in `0..n`.
pub fn mutate(bytes: &mut [u8], below: &mut impl FnMut(u32) -> u32) {
    for _ in 0..1 + below(3) {
        let at = below(bytes.len() as u32) as usize;
        match below(3) {
            0 => bytes[at] ^= 1 << below(8),
            1 => bytes[at] = below(256) as u8,
            _ => set(bytes, at & !3, below(64)),
        }
    }
}
