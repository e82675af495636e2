//! The vertex buffer of 001 (Fig. 4 and 5): what the host writes into memory for the
//! command parser to read, one frame of triangles as the hardware takes them. The README's
//! "Vertex buffer" gives it byte for byte; in short, little-endian 32-bit words:
//!
//! * a header of [`HEADER_BYTES`]: [`MAGIC`], [`VERSION`], flags (cull back faces), the
//!   screen, the size class and every number format of the build that draws it, the counts
//!   and byte offsets of the two arrays, the buffer's length, the background colour;
//! * the triangle index list: one [`RECORD_BYTES`] record per triangle, V0, V1, V2 (indices
//!   into the vertex array), TI (texture index, end-of-buffer and end-of-frame flags) and the
//!   triangle's three `inv_w` words (w_min / w over the triangle, so a property of the
//!   triangle, not of the vertex);
//! * the vertex information array: one [`RECORD_BYTES`] record per distinct vertex, x, y, z,
//!   R, G, B as raw fixed-point words at the header's formats, sign- or zero-extended to 32
//!   bits. A vertex shared by several triangles is stored once (001: "indices and vertex
//!   data are kept apart").
//!
//! Both arrays start on a [`RECORD_BYTES`] boundary and every record is that long, so a
//! record is one burst of a 32-, 64-, 128- or 256-bit memory bus.
//!
//! [`pack`] makes a buffer from a trilist through the host's front end (`guard_band`, then
//! `input::to_fixed`, as `raster_top::raster_top` does), [`VertexBuffer::encode`] writes it
//! and [`VertexBuffer::decode`] reads one back, checking every rule: an error names the
//! byte offset and the rule broken, and nothing panics on any input.

pub mod broken;

use crate::guard_band;
use crate::input::{to_fixed, InputError, Vtx};
use fx::{Build, Fmt, Formats, Overflow, Rounding};
use scene::{Trilist, Vertex};
use std::collections::HashMap;
use std::fmt;

/// The first four bytes.
pub const MAGIC: [u8; 4] = *b"EPVB";
/// The version this edgepaint writes and reads.
pub const VERSION: u16 = 1;
/// The header's length.
pub const HEADER_BYTES: usize = 96;
/// The length of an index record and of a vertex record, and the arrays' alignment.
pub const RECORD_BYTES: usize = 32;
/// TI's texture index of an untextured triangle (the command parser carries no texture yet).
pub const NO_TEXTURE: u16 = 0xffff;
/// TI: the last triangle of the buffer.
pub const END_OF_BUFFER: u32 = 1 << 16;
/// TI: the last triangle of the frame.
pub const END_OF_FRAME: u32 = 1 << 17;
/// Header flags: cull back faces.
pub const FLAG_CULL_BACK: u16 = 1;
/// The widest field a record holds.
const FIELD_BITS: u32 = 32;

/// One triangle of the index list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndexRecord {
    /// V0, V1, V2: the vertices, indices into the vertex array.
    pub v: [u32; 3],
    /// Each vertex's `inv_w` word in this triangle (w_min / w; 1 for the nearest).
    pub iw: [i128; 3],
    pub end_of_buffer: bool,
    pub end_of_frame: bool,
}

/// One vertex of the vertex array: raw words at the header's formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct VertexRecord {
    /// x, y: `xy`.
    pub x: i128,
    pub y: i128,
    /// z: `z`.
    pub z: i128,
    /// R, G, B: `color`.
    pub c: [i128; 3],
}

/// A frame's vertex buffer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VertexBuffer {
    /// The build that draws it: size class and every format.
    pub build: Build,
    pub width: u32,
    pub height: u32,
    pub cull_back: bool,
    pub background: [u8; 3],
    pub triangles: Vec<IndexRecord>,
    pub vertices: Vec<VertexRecord>,
}

/// Triangles of hardware words as a `width` x `height` trilist: each word's value exactly,
/// w chosen so that `input::to_fixed` at `f` gives back the `inv_w` words (none when every
/// one is 1), so that every engine draws these words.
pub fn words_trilist(f: &Formats, width: u32, height: u32, triangles: &[[Vtx; 3]]) -> Trilist {
    let one = 1i128 << f.inv_w.frac;
    let all_one = triangles.iter().all(|t| t.iter().all(|v| v.iw == one));
    let triangles = triangles
        .iter()
        .map(|tri| {
            tri.map(|v| {
                let c = v.c.map(|c| f.color.to_f64(c));
                let mut out = Vertex::new(f.xy.to_f64(v.x), f.xy.to_f64(v.y), f.z.to_f64(v.z), c);
                if !all_one {
                    out.w = Some(w_for(f.inv_w.to_f64(v.iw)));
                }
                out
            })
        })
        .collect();
    Trilist { width, height, triangles, textures: Vec::new() }
}

/// Why bytes are not a vertex buffer: the offset of the offending bytes and the rule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DecodeError {
    pub offset: usize,
    pub rule: String,
}

impl fmt::Display for DecodeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "offset {}: {}", self.offset, self.rule)
    }
}

impl std::error::Error for DecodeError {}

fn fail<T>(offset: usize, rule: impl Into<String>) -> Result<T, DecodeError> {
    Err(DecodeError { offset, rule: rule.into() })
}

/// A format as a header word: bits 0-7 integer bits, 8-15 fraction bits, 16 signed, 17
/// rounding half up (else truncate), 18 saturating (else wrapping), the rest 0.
pub fn format_word(f: Fmt) -> u32 {
    f.int
        | f.frac << 8
        | (f.signed as u32) << 16
        | ((f.rounding == Rounding::HalfUp) as u32) << 17
        | ((f.overflow == Overflow::Saturate) as u32) << 18
}

/// The format of a header word, if it is one.
fn word_format(w: u32) -> Option<Fmt> {
    let (int, frac) = (w & 0xff, (w >> 8) & 0xff);
    let f = Fmt {
        signed: w & 1 << 16 != 0,
        int,
        frac,
        rounding: if w & 1 << 17 != 0 { Rounding::HalfUp } else { Rounding::Truncate },
        overflow: if w & 1 << 18 != 0 { Overflow::Saturate } else { Overflow::Wrap },
    };
    (w >> 19 == 0 && f.bits() >= 1 && f.bits() <= fx::MAX_BITS).then_some(f)
}

/// The formats of a build from the header's words, in `Formats::named` order.
fn formats_of(words: [Fmt; 11]) -> Formats {
    let [xy, z, color, inv_w, ooa, ooa_d, dz, z_acc, dc, c_acc, bary] = words;
    Formats { xy, z, color, inv_w, ooa, ooa_d, dz, z_acc, dc, c_acc, bary }
}

/// The vertex fields' formats, by name, as a record holds them.
fn field_formats(f: &Formats) -> [(&'static str, Fmt); 4] {
    [("xy", f.xy), ("z", f.z), ("color", f.color), ("inv_w", f.inv_w)]
}

/// Why `build` cannot be written in a vertex buffer, if it cannot.
fn check_build(build: &Build, width: u32, height: u32) -> Result<(), String> {
    if let Some((name, f)) = field_formats(&build.formats).into_iter().find(|(_, f)| f.bits() > FIELD_BITS) {
        return Err(format!("a vertex buffer's fields are at most {FIELD_BITS} bits: {name} is {f}"));
    }
    let side = 1u64 << build.class.min(32);
    if !(1..=16).contains(&build.class) || u64::from(width.max(height)) > side {
        return Err(format!("size class {} does not draw a {width}x{height} screen", build.class));
    }
    scene::trilist::check_resolution(width, height).map_err(|e| e.to_string())?;
    build.formats.check(side as u32, side as u32)
}

/// A raw word of format `f` as the 32-bit field that holds it.
fn field(f: Fmt, raw: i128) -> u32 {
    debug_assert!(f.fits(raw), "{raw} fits {f}");
    raw as u32
}

/// The raw word of format `f` a 32-bit field holds, if it holds one.
fn unfield(f: Fmt, w: u32) -> Option<i128> {
    let raw = if f.signed { w as i32 as i128 } else { w as i128 };
    f.fits(raw).then_some(raw)
}

/// The vertex buffer of `list` for `build`: the triangles the host's front end sends
/// (`guard_band::pieces` for the scanline pipeline, then `input::to_fixed`), each distinct
/// vertex stored once. Triangles that do not fit the formats are left out and returned
/// with their index in `list`; an error when the build cannot be written in a buffer.
pub fn pack(
    list: &Trilist,
    build: &Build,
    cull_back: bool,
    background: [u8; 3],
) -> Result<(VertexBuffer, Vec<(usize, InputError)>), String> {
    check_build(build, list.width, list.height)?;
    let f = &build.formats;
    let pieces = guard_band::pieces(list, f, false);
    let mut vb = VertexBuffer {
        build: *build,
        width: list.width,
        height: list.height,
        cull_back,
        background,
        triangles: Vec::new(),
        vertices: Vec::new(),
    };
    let mut skipped = Vec::new();
    let mut index = HashMap::new();
    for (t, &i) in pieces.triangles.iter().zip(&pieces.source) {
        let tri = match to_fixed(t, f) {
            Ok(tri) => tri,
            Err(e) => {
                skipped.push((i, e));
                continue;
            }
        };
        let v = tri.map(|v| {
            let r = VertexRecord { x: v.x, y: v.y, z: v.z, c: v.c };
            *index.entry(r).or_insert_with(|| {
                vb.vertices.push(r);
                vb.vertices.len() as u32 - 1
            })
        });
        let iw = tri.map(|v| v.iw);
        vb.triangles.push(IndexRecord { v, iw, end_of_buffer: false, end_of_frame: false });
    }
    if let Some(last) = vb.triangles.last_mut() {
        (last.end_of_buffer, last.end_of_frame) = (true, true);
    }
    let bytes = HEADER_BYTES + RECORD_BYTES * (vb.triangles.len() + vb.vertices.len());
    if u32::try_from(bytes).is_err() {
        return Err(format!(
            "{} triangles make a buffer of {bytes} bytes, more than 32-bit offsets reach",
            list.triangles.len()
        ));
    }
    Ok((vb, skipped))
}

impl VertexBuffer {
    /// Byte offset of the triangle index list (right after the header).
    pub fn index_offset(&self) -> usize {
        HEADER_BYTES
    }

    /// Byte offset of the vertex array (right after the index list).
    pub fn vertex_offset(&self) -> usize {
        HEADER_BYTES + RECORD_BYTES * self.triangles.len()
    }

    /// Triangle `t` as the hardware takes it.
    pub fn triangle(&self, t: &IndexRecord) -> [Vtx; 3] {
        [0, 1, 2].map(|k| {
            let r = self.vertices[t.v[k] as usize];
            Vtx { x: r.x, y: r.y, z: r.z, c: r.c, iw: t.iw[k] }
        })
    }

    /// Every triangle as the hardware takes it, in order.
    pub fn hardware_triangles(&self) -> Vec<[Vtx; 3]> {
        self.triangles.iter().map(|t| self.triangle(t)).collect()
    }

    /// The buffer's triangles as a trilist: each word's value exactly, w chosen so that
    /// `input::to_fixed` gives back the buffer's `inv_w` words (none when every one is 1),
    /// so that every engine draws the buffer's words.
    pub fn to_trilist(&self) -> Trilist {
        words_trilist(&self.build.formats, self.width, self.height, &self.hardware_triangles())
    }

    /// The buffer's bytes.
    pub fn encode(&self) -> Vec<u8> {
        let f = &self.build.formats;
        let mut out = Vec::with_capacity(self.vertex_offset() + RECORD_BYTES * self.vertices.len());
        let mut put = |w: u32| out.extend_from_slice(&w.to_le_bytes());
        put(u32::from_le_bytes(MAGIC));
        put(VERSION as u32 | ((if self.cull_back { FLAG_CULL_BACK } else { 0 }) as u32) << 16);
        put(self.width | self.height << 16);
        put(self.build.class);
        put(self.triangles.len() as u32);
        put(self.vertices.len() as u32);
        put(self.index_offset() as u32);
        put(self.vertex_offset() as u32);
        put((self.vertex_offset() + RECORD_BYTES * self.vertices.len()) as u32);
        let [r, g, b] = self.background;
        put(u32::from_le_bytes([r, g, b, 0]));
        for (_, fmt) in f.named() {
            put(format_word(fmt));
        }
        for _ in 0..3 {
            put(0);
        }
        for t in &self.triangles {
            let flags = (t.end_of_buffer as u32 * END_OF_BUFFER) | (t.end_of_frame as u32 * END_OF_FRAME);
            for w in t.v {
                put(w);
            }
            put(NO_TEXTURE as u32 | flags);
            for iw in t.iw {
                put(field(f.inv_w, iw));
            }
            put(0);
        }
        for v in &self.vertices {
            for w in [field(f.xy, v.x), field(f.xy, v.y), field(f.z, v.z)] {
                put(w);
            }
            for c in v.c {
                put(field(f.color, c));
            }
            put(0);
            put(0);
        }
        out
    }

    /// Reads a buffer, checking every rule of the format (README, "Vertex buffer"): the
    /// header ([`read_header`]), the length, then each vertex record
    /// ([`read_vertex_record`]) and each index record ([`read_index_record`]).
    pub fn decode(bytes: &[u8]) -> Result<VertexBuffer, DecodeError> {
        if bytes.len() < HEADER_BYTES {
            return fail(
                bytes.len(),
                format!("the buffer ends inside its {HEADER_BYTES}-byte header ({} bytes)", bytes.len()),
            );
        }
        let located = |at: usize| move |e: Broken| DecodeError { offset: at + e.at, rule: e.rule };
        let h = read_header(&words(bytes, 0), None).map_err(located(0))?;
        if h.length as usize != bytes.len() {
            return fail(
                32,
                format!("the header gives the buffer's length as {} bytes; it has {}", h.length, bytes.len()),
            );
        }
        let mut vb = VertexBuffer {
            build: h.build,
            width: h.width,
            height: h.height,
            cull_back: h.cull_back,
            background: h.background,
            triangles: Vec::with_capacity(h.triangles as usize),
            vertices: Vec::with_capacity(h.vertices as usize),
        };
        for v in 0..h.vertices {
            let at = h.vertex_at as usize + v as usize * RECORD_BYTES;
            vb.vertices.push(read_vertex_record(&words(bytes, at), v, &h.build.formats).map_err(located(at))?);
        }
        for t in 0..h.triangles {
            let at = h.index_at as usize + t as usize * RECORD_BYTES;
            vb.triangles.push(read_index_record(&words(bytes, at), t, &h).map_err(located(at))?);
        }
        Ok(vb)
    }
}

/// The `N` little-endian 32-bit words from byte `at` (inside `bytes`).
fn words<const N: usize>(bytes: &[u8], at: usize) -> [u32; N] {
    std::array::from_fn(|i| {
        let o = at + 4 * i;
        u32::from_le_bytes([bytes[o], bytes[o + 1], bytes[o + 2], bytes[o + 3]])
    })
}

/// A header's or a record's words breaking a rule: the byte offset inside it, the rule
/// and its class ([`Fault`], the command parser's error code).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Broken {
    pub at: usize,
    pub fault: Fault,
    pub rule: String,
}

fn broken<T>(at: usize, fault: Fault, rule: impl Into<String>) -> Result<T, Broken> {
    Err(Broken { at, fault, rule: rule.into() })
}

/// The class of a rule a buffer breaks: the command parser's error code
/// (`model::command_parser`), one per class.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Fault {
    /// Not "EPVB".
    Magic = 1,
    /// Not version [`VERSION`].
    Version = 2,
    /// A reserved bit, byte or word is not 0.
    Reserved = 3,
    /// The size class or a format word is not a build's, or is not the hardware's.
    Build = 4,
    /// The arrays' offsets and counts: before the header's end, off a record boundary,
    /// past the buffer's length, overlapping, or past 32-bit addresses.
    Layout = 5,
    /// A vertex index past the vertex array.
    Index = 6,
    /// TI: a texture, a reserved bit, or end flags on the wrong record.
    TriangleInfo = 7,
    /// An `inv_w` word outside its format, or none of a triangle's is 1.
    InvW = 8,
    /// A vertex word outside its format.
    VertexWord = 9,
    /// The memory answered a read with an error (the command parser only).
    Bus = 10,
    /// The buffer's address is not on a record boundary (the command parser only).
    Address = 11,
    /// The header's screen is larger than the buffers the host gave the core (the command
    /// parser only: its `screen` input).
    Screen = 12,
}

/// What the header says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Header {
    pub build: Build,
    pub width: u32,
    pub height: u32,
    pub cull_back: bool,
    pub background: [u8; 3],
    /// T and V.
    pub triangles: u32,
    pub vertices: u32,
    /// Byte offsets of the index list and the vertex array.
    pub index_at: u32,
    pub vertex_at: u32,
    /// The buffer's length in bytes.
    pub length: u32,
}

/// The header's 24 words, checked: every rule that needs only the header (the length is
/// the buffer's is the reader's to check). `hardware`, when given, is the build that will
/// draw the buffer (the command parser's): a buffer for another is refused where the
/// header's build is read, before its screen and layout, so that the parser's RTL compares
/// the build's words with its own.
pub fn read_header(h: &[u32; HEADER_BYTES / 4], hardware: Option<&Build>) -> Result<Header, Broken> {
    if h[0] != u32::from_le_bytes(MAGIC) {
        let magic = h[0].to_le_bytes();
        return broken(0, Fault::Magic, format!("not a vertex buffer: the magic is {magic:02x?}, not \"EPVB\""));
    }
    let version = h[1] as u16;
    if version != VERSION {
        return broken(4, Fault::Version, format!("version {version}: this edgepaint reads version {VERSION}"));
    }
    let flags = (h[1] >> 16) as u16;
    if flags & !FLAG_CULL_BACK != 0 {
        return broken(6, Fault::Reserved, format!("flags {flags:#06x}: only bit 0 (cull back faces) is defined"));
    }
    let (width, height) = (h[2] & 0xffff, h[2] >> 16);
    let background = h[9].to_le_bytes();
    if background[3] != 0 || h[21..24].iter().any(|&w| w != 0) {
        let at = if background[3] != 0 { 39 } else { 84 };
        return broken(at, Fault::Reserved, "reserved header bytes must be 0");
    }
    let mut fmts = [Fmt::s(0, 0); 11];
    for (i, (name, _)) in Formats::for_n(10).named().iter().enumerate() {
        fmts[i] = word_format(h[10 + i]).ok_or(Broken {
            at: 40 + 4 * i,
            fault: Fault::Build,
            rule: format!(
                "{name}'s format word {:#010x} is not a format (bits 0-18 only, 1 to {} bits)",
                h[10 + i],
                fx::MAX_BITS
            ),
        })?;
    }
    let build = Build { class: h[3], formats: formats_of(fmts) };
    if let Some(hw) = hardware.filter(|&hw| *hw != build) {
        let rule = format!("the buffer is for {build:?}; this hardware draws {hw:?}");
        return Err(Broken { at: 12, fault: Fault::Build, rule });
    }
    check_build(&build, width, height).map_err(|rule| Broken { at: 8, fault: Fault::Build, rule })?;
    let header = Header {
        build,
        width,
        height,
        cull_back: flags & FLAG_CULL_BACK != 0,
        background: [background[0], background[1], background[2]],
        triangles: h[4],
        vertices: h[5],
        index_at: h[6],
        vertex_at: h[7],
        length: h[8],
    };
    let region = |at: u32, n: u32, what: &str, field: usize| -> Result<(), Broken> {
        let end = u64::from(at) + u64::from(n) * RECORD_BYTES as u64;
        if !at.is_multiple_of(RECORD_BYTES as u32) || (at as usize) < HEADER_BYTES {
            return broken(
                field,
                Fault::Layout,
                format!("the {what} starts at byte {at}: past the header, on a {RECORD_BYTES}-byte boundary"),
            );
        }
        if end > u64::from(header.length) {
            return broken(
                field,
                Fault::Layout,
                format!("{n} records of the {what} from byte {at} run past the buffer's {} bytes", header.length),
            );
        }
        Ok(())
    };
    let (t, v) = (header.triangles, header.vertices);
    region(header.index_at, t, "index list", 24)?;
    region(header.vertex_at, v, "vertex array", 28)?;
    let (i0, v0) = (u64::from(header.index_at), u64::from(header.vertex_at));
    let record = RECORD_BYTES as u64;
    if t > 0 && v > 0 && i0 < v0 + record * u64::from(v) && v0 < i0 + record * u64::from(t) {
        return broken(28, Fault::Layout, "the index list and the vertex array overlap");
    }
    Ok(header)
}

/// Vertex record `v`'s 8 words at the formats `f`, checked.
pub fn read_vertex_record(w: &[u32; RECORD_BYTES / 4], v: u32, f: &Formats) -> Result<VertexRecord, Broken> {
    let get = |i: usize, name: &str, fmt: Fmt| {
        unfield(fmt, w[i]).ok_or(Broken {
            at: 4 * i,
            fault: Fault::VertexWord,
            rule: format!("vertex {v}: {name} = {:#010x} is not a {fmt} word, sign- or zero-extended", w[i]),
        })
    };
    let r = VertexRecord {
        x: get(0, "x", f.xy)?,
        y: get(1, "y", f.xy)?,
        z: get(2, "z", f.z)?,
        c: [get(3, "R", f.color)?, get(4, "G", f.color)?, get(5, "B", f.color)?],
    };
    if w[6] != 0 || w[7] != 0 {
        return broken(24, Fault::Reserved, format!("vertex {v}: reserved words must be 0"));
    }
    Ok(r)
}

/// Index record `t`'s 8 words in the buffer of header `h`, checked.
pub fn read_index_record(w: &[u32; RECORD_BYTES / 4], t: u32, h: &Header) -> Result<IndexRecord, Broken> {
    let vertices = h.vertices;
    let v = [w[0], w[1], w[2]];
    if let Some(k) = (0..3).find(|&k| v[k] >= vertices) {
        return broken(4 * k, Fault::Index, format!("triangle {t}: V{k} = {} is past the {vertices} vertices", v[k]));
    }
    let ti = w[3];
    let texture = ti as u16;
    if texture != NO_TEXTURE {
        return broken(
            12,
            Fault::TriangleInfo,
            format!(
                "triangle {t}: texture index {texture}: the command parser carries no texture ({NO_TEXTURE:#06x}: none)"
            ),
        );
    }
    if ti & !(0xffff | END_OF_BUFFER | END_OF_FRAME) != 0 {
        return broken(12, Fault::TriangleInfo, format!("triangle {t}: TI {ti:#010x}: bits 18-31 are reserved (0)"));
    }
    let last = t + 1 == h.triangles;
    let (eob, eof) = (ti & END_OF_BUFFER != 0, ti & END_OF_FRAME != 0);
    if eob != last {
        let rule =
            if last { "the last triangle must end the buffer" } else { "only the last triangle ends the buffer" };
        return broken(12, Fault::TriangleInfo, format!("triangle {t}: {rule} (TI bit 16)"));
    }
    if eof && !last {
        return broken(
            12,
            Fault::TriangleInfo,
            format!("triangle {t}: only the buffer's last triangle can end the frame (TI bit 17)"),
        );
    }
    let f = &h.build.formats;
    let one = 1i128 << f.inv_w.frac;
    let mut iw = [0; 3];
    for k in 0..3 {
        // 0 is a word: a vertex over 2^(frac + 1) times as far as the nearest one.
        iw[k] = unfield(f.inv_w, w[4 + k]).filter(|&iw| iw >= 0).ok_or(Broken {
            at: 16 + 4 * k,
            fault: Fault::InvW,
            rule: format!("triangle {t}: inv_w of V{k} = {:#010x} is not a {} word", w[4 + k], f.inv_w),
        })?;
    }
    if iw.iter().max() != Some(&one) {
        return broken(
            16,
            Fault::InvW,
            format!("triangle {t}: inv_w is w_min / w over the triangle: its largest must be 1"),
        );
    }
    if w[7] != 0 {
        return broken(28, Fault::Reserved, format!("triangle {t}: reserved word must be 0"));
    }
    Ok(IndexRecord { v, iw, end_of_buffer: eob, end_of_frame: eof })
}

/// A w whose reciprocal in f64 is `iw` exactly (`input::to_fixed` divides the triangle's
/// smallest w, 1 here, by it): 1 / iw, or the nearest f64 beside it that gives it back.
/// For `iw` 0, 2^64: its reciprocal rounds to 0 in any `inv_w` format edgepaint builds.
fn w_for(iw: f64) -> f64 {
    if iw == 0.0 {
        return 2f64.powi(64);
    }
    let w = 1.0 / iw;
    let step = |x: f64, up: bool| f64::from_bits(if up { x.to_bits() + 1 } else { x.to_bits() - 1 });
    [w, step(w, true), step(w, false), step(step(w, true), true), step(step(w, false), false)]
        .into_iter()
        .find(|&w| 1.0 / w == iw)
        .unwrap_or(w)
}

#[cfg(test)]
mod tests {
    use super::*;
    use scene::Triangle;

    fn tri(p: [(f64, f64, f64); 3], w: Option<[f64; 3]>) -> Triangle {
        let mut t = p.map(|(x, y, z)| Vertex::new(x, y, z, [200.0, 100.0, 50.0]));
        if let Some(w) = w {
            for k in 0..3 {
                t[k].w = Some(w[k]);
            }
        }
        t
    }

    /// A fan of four triangles around a centre: 5 distinct vertices, not 12.
    fn fan() -> Trilist {
        let c = (8.0, 8.0, 0.5);
        let rim = [(1.0, 1.0, 0.2), (15.0, 1.0, 0.3), (15.0, 15.0, 0.4), (1.0, 15.0, 0.6)];
        let triangles = (0..4).map(|i| tri([c, rim[i], rim[(i + 1) % 4]], None)).collect();
        Trilist { width: 16, height: 16, triangles, textures: Vec::new() }
    }

    fn packed(list: &Trilist) -> VertexBuffer {
        pack(list, &Build::for_screen(list.width, list.height), true, [1, 2, 3]).expect("packs").0
    }

    #[test]
    fn shared_vertices_are_stored_once_and_the_buffer_reads_back() {
        let vb = packed(&fan());
        assert_eq!((vb.triangles.len(), vb.vertices.len()), (4, 5));
        let bytes = vb.encode();
        assert_eq!(bytes.len(), HEADER_BYTES + 9 * RECORD_BYTES);
        assert_eq!(&bytes[..4], b"EPVB");
        // The last triangle ends the buffer and the frame; no other does.
        assert_eq!(words::<4>(&bytes, HEADER_BYTES + 3 * RECORD_BYTES)[3], 0xffff | END_OF_BUFFER | END_OF_FRAME);
        assert_eq!(words::<4>(&bytes, HEADER_BYTES)[3], 0xffff);
        assert_eq!(VertexBuffer::decode(&bytes), Ok(vb));
    }

    #[test]
    fn the_buffer_holds_the_words_to_fixed_makes() {
        let list = fan();
        let vb = packed(&list);
        let f = Build::for_screen(16, 16).formats;
        let want: Vec<_> = list.triangles.iter().map(|t| to_fixed(t, &f).expect("fits")).collect();
        assert_eq!(vb.hardware_triangles(), want);
        // And back through a trilist: the same words.
        let again: Vec<_> = vb.to_trilist().triangles.iter().map(|t| to_fixed(t, &f).expect("fits")).collect();
        assert_eq!(again, want);
    }

    #[test]
    fn inv_w_words_survive_the_trilist_for_every_value() {
        let f = Build::default().formats.inv_w;
        for raw in 0..=(1i128 << f.frac) {
            let iw = f.to_f64(raw);
            assert_eq!(f.from_f64(1.0 / w_for(iw)), Some(raw), "inv_w {raw}");
        }
    }

    /// One 16 x 16 triangle with vertices at distances `w` through `pack`, `encode`,
    /// `decode` and `to_trilist`: the buffer holds `input::to_fixed`'s words and gives them
    /// back at each step. Returns them.
    fn round_trip(w: [f64; 3]) -> [Vtx; 3] {
        let list = Trilist {
            width: 16,
            height: 16,
            triangles: vec![tri([(1.0, 1.0, 0.2), (15.0, 2.0, 0.4), (3.0, 14.0, 0.9)], Some(w))],
            textures: Vec::new(),
        };
        let f = Build::for_screen(16, 16).formats;
        let want = to_fixed(&list.triangles[0], &f).expect("fits");
        let vb = packed(&list);
        assert_eq!(vb.hardware_triangles(), vec![want]);
        let back = VertexBuffer::decode(&vb.encode()).expect("reads back");
        assert_eq!(back.hardware_triangles(), vec![want]);
        let again = to_fixed(&back.to_trilist().triangles[0], &f).expect("fits");
        assert_eq!(again, want);
        want
    }

    #[test]
    fn perspective_triangles_keep_their_inv_w() {
        let iw = round_trip([1.5, 3.0, 7.25]).map(|v| v.iw);
        assert!(iw[0] == 1 << 15 && iw[1] < iw[0] && iw[2] < iw[1], "{iw:?}");
    }

    /// A vertex a million times as far as the nearest has `inv_w` word 0 (w_min / w under
    /// half of U1.15's LSB): the buffer stores it, reads it back and gives it back through
    /// the trilist.
    #[test]
    fn a_vertex_far_past_the_inv_w_format_reads_back_as_0() {
        assert_eq!(round_trip([1.0, 1e6, 2.0]).map(|v| v.iw), [1 << 15, 0, 1 << 14]);
    }

    /// Bytes of the fan's buffer with `edit` applied; the rule broken must name `offset`.
    fn broken(edit: impl Fn(&mut Vec<u8>), offset: usize, says: &str) {
        let mut bytes = packed(&fan()).encode();
        edit(&mut bytes);
        let e = VertexBuffer::decode(&bytes).expect_err(says);
        assert_eq!(e.offset, offset, "{e}");
        assert!(e.rule.contains(says), "{e} should say {says:?}");
    }

    fn set(bytes: &mut [u8], at: usize, w: u32) {
        bytes[at..at + 4].copy_from_slice(&w.to_le_bytes());
    }

    #[test]
    fn broken_buffers_name_the_offset_and_the_rule() {
        let tri = |t: usize| HEADER_BYTES + t * RECORD_BYTES;
        let vtx = |v: usize| HEADER_BYTES + 4 * RECORD_BYTES + v * RECORD_BYTES;
        broken(|b| b.truncate(50), 50, "ends inside its 96-byte header");
        broken(|b| b[0] = b'X', 0, "not a vertex buffer");
        broken(|b| b[4] = 2, 4, "version 2");
        broken(|b| b[6] = 4, 6, "only bit 0");
        broken(|b| b.truncate(b.len() - 8), 32, "length");
        broken(|b| set(b, 16, 1000), 24, "run past the buffer");
        broken(|b| set(b, 24, 100), 24, "on a 32-byte boundary");
        broken(|b| set(b, 28, HEADER_BYTES as u32), 28, "overlap");
        broken(|b| set(b, 40, 0xff_ffff), 40, "xy's format word");
        broken(|b| set(b, 12, 3), 8, "size class 3");
        broken(|b| set(b, tri(1) + 4, 5), tri(1) + 4, "V1 = 5 is past the 5 vertices");
        broken(|b| set(b, tri(3) + 12, 0xffff), tri(3) + 12, "the last triangle must end the buffer");
        broken(|b| set(b, tri(0) + 12, 0xffff | END_OF_BUFFER), tri(0) + 12, "only the last triangle ends");
        broken(|b| set(b, tri(0) + 12, 0xffff | END_OF_FRAME), tri(0) + 12, "only the buffer's last triangle");
        broken(|b| set(b, tri(2) + 12, 7), tri(2) + 12, "carries no texture");
        broken(|b| set(b, tri(2) + 20, 0xffff_ffff), tri(2) + 20, "inv_w of V1 = 0xffffffff is not a");
        let halves = |b: &mut Vec<u8>| (0..3).for_each(|k| set(b, tri(2) + 16 + 4 * k, 1 << 14));
        broken(halves, tri(2) + 16, "its largest must be 1");
        broken(|b| set(b, tri(2) + 28, 1), tri(2) + 28, "reserved");
        broken(|b| set(b, vtx(1) + 8, 0x7fff_ffff), vtx(1) + 8, "vertex 1: z");
        broken(|b| set(b, vtx(4) + 16, 0xffff_ffff), vtx(4) + 16, "vertex 4: G");
        broken(|b| set(b, vtx(0) + 28, 9), vtx(0) + 24, "reserved words");
    }

    /// Random edits of a good buffer never panic: each reads back or names an offset inside
    /// the buffer (or its end).
    #[test]
    fn mutated_buffers_never_panic() {
        use rand::{Rng, SeedableRng};
        let good = packed(&fan()).encode();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        for _ in 0..20_000 {
            let mut b = good.clone();
            for _ in 0..rng.gen_range(1..4) {
                match rng.gen_range(0..3) {
                    0 => {
                        let i = rng.gen_range(0..b.len());
                        b[i] = rng.gen();
                    }
                    1 => b.truncate(rng.gen_range(0..b.len())),
                    _ => b.extend((0..rng.gen_range(1..40)).map(|_| rng.gen::<u8>())),
                }
                if b.is_empty() {
                    break;
                }
            }
            if let Err(e) = VertexBuffer::decode(&b) {
                assert!(e.offset <= b.len().max(HEADER_BYTES), "{e} in a buffer of {}", b.len());
            }
        }
    }

    #[test]
    fn fields_wider_than_32_bits_cannot_be_packed() {
        let mut build = Build::for_screen(16, 16);
        build.formats.z = Fmt::s(1, 40);
        let e = pack(&fan(), &build, false, [0; 3]).expect_err("z is 42 bits");
        assert!(e.contains("z is S1.40"), "{e}");
    }
}
