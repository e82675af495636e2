//! The depth and colour buffers behind `pixel_out`'s memory port, in Rust (see
//! `rtl::pixel_out` for the port's contract): one word per chunk of `lanes` pixels of a row
//! at address `{y, x / lanes}` (`x / lanes` in the low `n` - log2 `lanes` bits for size
//! class `n`; one lane: a word per pixel at `{y, x}`), an enable per lane, reads returning
//! data the cycle after (the depth, and for the blending `pixel_out` the colour too),
//! `mem$ready` stalling both.

use crate::streams::unsigned;
use crate::{Outputs, Value};
use model::pixel_out::Framebuffer;
use rtl::widths::CHANNEL;

/// What a read of an address written at the same edge returns: `pixel_out` must work
/// with either.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReadDuringWrite {
    /// The word as it was before the write (block RAM in read-first mode).
    Old,
    /// The word just written (write-first).
    New,
}

/// The most lanes a memory word holds (`rtl::vector`'s `LANES`: 1, 2, 4 or 8).
pub const MAX_LANES: usize = 8;

/// One pixel the memory wrote.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Write {
    pub x: u32,
    pub y: u32,
    pub z: u32,
    pub rgb: [u8; 3],
}

/// The pixels one edge wrote, lowest lane first.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Writes {
    n: usize,
    at: [Write; MAX_LANES],
}

impl Writes {
    pub fn as_slice(&self) -> &[Write] {
        &self.at[..self.n]
    }
}

/// Field `i` (`width` bits at bit `i width`) of the little-endian words `words`.
pub fn field(words: &[u64], width: usize, i: usize) -> u32 {
    let lo = i * width;
    let (w, b) = (lo / 64, lo % 64);
    let mut v = words.get(w).copied().unwrap_or(0) >> b;
    if b + width > 64 {
        v |= words.get(w + 1).copied().unwrap_or(0) << (64 - b);
    }
    (v & ((1u64 << width) - 1)) as u32
}

/// `lanes` fields of `width` bits each ([`field`]).
pub fn unpack(words: &[u64], width: usize, lanes: usize) -> [u32; MAX_LANES] {
    std::array::from_fn(|i| if i < lanes { field(words, width, i) } else { 0 })
}

/// The first `lanes` of `fields`, `width` bits each, side by side in `words` (as many as
/// they fill), little-endian.
pub fn pack_words(fields: &[u32], width: usize, lanes: usize, words: &mut [u64]) {
    words.fill(0);
    for (i, &f) in fields[..lanes].iter().enumerate() {
        let (w, b) = ((i * width) / 64, (i * width) % 64);
        words[w] |= (f as u64) << b;
        if b + width > 64 {
            words[w + 1] |= (f as u64) >> (64 - b);
        }
    }
}

/// [`pack_words`] as a value.
pub fn pack(fields: &[u32], width: usize, lanes: usize) -> Value {
    let mut words = vec![0u64; (lanes * width).div_ceil(64)];
    pack_words(fields, width, lanes, &mut words);
    Value::from_words(lanes * width, &words)
}

/// The memory's request in one cycle, as `pixel_out` (or `raster_top`) drives it: a word
/// of `lanes` pixels (`rtl::links::ChunkPort`; one lane: `MemoryPort`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Request {
    /// The lanes read and written (bit i: lane i).
    pub rd_en: u8,
    pub rd_addr: u32,
    pub wr_en: u8,
    pub wr_addr: u32,
    /// Per lane, the depth and the colour `{R, G, B}` written.
    pub wr_z: [u32; MAX_LANES],
    pub wr_rgb: [u32; MAX_LANES],
}

/// The output ports a [`Request`] is read off.
pub const REQUEST: [&str; 6] = ["mem$rd_en", "mem$rd_addr", "mem$wr_en", "mem$wr_addr", "mem$wr_z", "mem$wr_rgb"];

impl Request {
    /// Read off a unit's outputs (`mem$rd_en`, ... `mem$wr_rgb`), its lanes from the width
    /// of `mem$wr_en`.
    pub fn of(o: &Outputs) -> Request {
        let get = |p: &str| unsigned(o.get(p)) as u32;
        let lanes = o.get("mem$wr_en").width();
        let (z, rgb) = (o.get("mem$wr_z"), o.get("mem$wr_rgb"));
        Request {
            rd_en: get("mem$rd_en") as u8,
            rd_addr: get("mem$rd_addr"),
            wr_en: get("mem$wr_en") as u8,
            wr_addr: get("mem$wr_addr"),
            wr_z: unpack(z.words(), z.width() / lanes, lanes),
            wr_rgb: unpack(rgb.words(), 3 * CHANNEL, lanes),
        }
    }
}

/// Depth and colour buffers of a `width` x `height` screen.
#[derive(Clone, Debug)]
pub struct Memory {
    pub width: u32,
    pub height: u32,
    /// Depth per pixel, row-major from the top-left.
    pub depth: Vec<u32>,
    pub rgb: Vec<[u8; 3]>,
    /// Whether a pixel was ever written.
    pub written: Vec<bool>,
    /// Pixels written so far.
    pub writes: u64,
    /// Pixels whose depth was read so far.
    pub reads: u64,
    /// Pixels a word, and the address bits of the word's place in its row.
    lanes: u32,
    x_bits: u32,
    read_during_write: ReadDuringWrite,
    rd_z: [u32; MAX_LANES],
    rd_rgb: [u32; MAX_LANES],
}

impl Memory {
    /// Buffers cleared to depth `z_max` and colour `background`, for the `pixel_out` of size
    /// class `class` with `lanes` pixels a word (1, 2, 4 or 8).
    pub fn new(
        class: u32,
        lanes: u32,
        (width, height): (u32, u32),
        z_max: u32,
        background: [u8; 3],
        rdw: ReadDuringWrite,
    ) -> Self {
        assert!(lanes.is_power_of_two() && lanes as usize <= MAX_LANES, "{lanes} lanes");
        let n = (width * height) as usize;
        Memory {
            width,
            height,
            lanes,
            x_bits: class - lanes.trailing_zeros(),
            depth: vec![z_max; n],
            rgb: vec![background; n],
            written: vec![false; n],
            writes: 0,
            reads: 0,
            read_during_write: rdw,
            rd_z: [0; MAX_LANES],
            rd_rgb: [0; MAX_LANES],
        }
    }

    /// The first pixel, in raster order, whose colour or depth differs from `fb`'s (the
    /// model's), named with both values; `None` when the buffers are equal.
    pub fn differs_from(&self, fb: &Framebuffer) -> Option<String> {
        if (self.width, self.height) != (fb.width, fb.height) {
            return Some(format!("a {}x{} memory against a {}x{} frame", self.width, self.height, fb.width, fb.height));
        }
        let at = |i: usize| (i as u32 % self.width, i as u32 / self.width);
        let colour = (0..self.rgb.len()).find(|&i| self.rgb[i] != fb.rgb[i]);
        let depth = (0..self.depth.len()).find(|&i| self.depth[i] != fb.depth[i]);
        match (colour, depth) {
            (Some(i), d) if d.is_none_or(|d| i <= d) => {
                Some(format!("colour of pixel {:?}: RTL {:?}, model {:?}", at(i), self.rgb[i], fb.rgb[i]))
            }
            (_, Some(i)) => Some(format!("depth of pixel {:?}: RTL {}, model {}", at(i), self.depth[i], fb.depth[i])),
            _ => None,
        }
    }

    /// `rd_z`: the depths last read, per lane (a lane not read keeps its last).
    pub fn rd_z(&self) -> [u32; MAX_LANES] {
        self.rd_z
    }

    /// `rd_z` as the port `mem$rd_z` of `depth`-bit lanes takes it.
    pub fn rd_z_value(&self, depth: usize) -> Value {
        pack(&self.rd_z, depth, self.lanes as usize)
    }

    /// The colours last read, per lane, as the port `mem$rd_rgb` of the blending
    /// `pixel_out` takes them (`{R, G, B}`, R on top).
    pub fn rd_rgb_value(&self) -> Value {
        pack(&self.rd_rgb, 3 * CHANNEL, self.lanes as usize)
    }

    /// Lane `lane`'s pixel `(x, y)` of the word at address `addr`.
    fn xy(&self, addr: u32, lane: usize) -> (u32, u32) {
        ((addr & ((1 << self.x_bits) - 1)) * self.lanes + lane as u32, addr >> self.x_bits)
    }

    fn index(&self, addr: u32, lane: usize, what: &str) -> usize {
        let (x, y) = self.xy(addr, lane);
        assert!(
            x < self.width && y < self.height,
            "{what} of ({x}, {y}), off the {}x{} screen",
            self.width,
            self.height
        );
        (y * self.width + x) as usize
    }

    /// One rising edge with `req` asked for: with `mem$ready` the memory performs the
    /// read and the write, lane by lane. Returns the pixels written.
    pub fn edge(&mut self, mem_ready: bool, req: &Request) -> Writes {
        let mut out = Writes::default();
        if !mem_ready {
            return out;
        }
        let lanes = self.lanes as usize;
        let on = |mask: u8, i: usize| mask >> i & 1 == 1;
        let read: [Option<usize>; MAX_LANES] =
            std::array::from_fn(|i| (i < lanes && on(req.rd_en, i)).then(|| self.index(req.rd_addr, i, "read")));
        if self.read_during_write == ReadDuringWrite::Old {
            self.take_reads(&read);
        }
        for i in (0..lanes).filter(|&i| on(req.wr_en, i)) {
            let at = self.index(req.wr_addr, i, "write");
            let c = req.wr_rgb[i];
            let rgb = [c >> (2 * CHANNEL), c >> CHANNEL, c].map(|c| c as u8);
            self.depth[at] = req.wr_z[i];
            self.rgb[at] = rgb;
            self.written[at] = true;
            self.writes += 1;
            let (x, y) = self.xy(req.wr_addr, i);
            out.at[out.n] = Write { x, y, z: req.wr_z[i], rgb };
            out.n += 1;
        }
        if self.read_during_write == ReadDuringWrite::New {
            self.take_reads(&read);
        }
        out
    }

    fn take_reads(&mut self, read: &[Option<usize>; MAX_LANES]) {
        for (lane, at) in read.iter().enumerate() {
            if let Some(at) = *at {
                self.rd_z[lane] = self.depth[at];
                let [r, g, b] = self.rgb[at].map(u32::from);
                self.rd_rgb[lane] = (r << (2 * CHANNEL)) | (g << CHANNEL) | b;
                self.reads += 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{pack, unpack, Memory, ReadDuringWrite, Request, Write, MAX_LANES};
    use model::pixel_out::Framebuffer;

    #[test]
    fn differs_from_names_the_first_pixel_that_differs() {
        let mut fb = Framebuffer::new(4, 3, 100, [1, 2, 3]);
        let mut mem = Memory::new(2, 1, (4, 3), 100, [1, 2, 3], ReadDuringWrite::Old);
        assert_eq!(mem.differs_from(&fb), None);
        fb.depth[2 * 4 + 1] = 7;
        assert_eq!(mem.differs_from(&fb).unwrap(), "depth of pixel (1, 2): RTL 100, model 7");
        mem.rgb[4 + 3] = [9, 9, 9];
        assert_eq!(mem.differs_from(&fb).unwrap(), "colour of pixel (3, 1): RTL [9, 9, 9], model [1, 2, 3]");
        let small = Framebuffer::new(2, 2, 100, [1, 2, 3]);
        assert_eq!(mem.differs_from(&small).unwrap(), "a 4x3 memory against a 2x2 frame");
    }

    #[test]
    fn pack_and_unpack_fields_across_words() {
        let f = [0xabcdef, 0x123456, 0xfedcba, 0x0f0f0f, 0, 0, 0, 0];
        let v = pack(&f, 24, 4);
        assert_eq!(v.width(), 96);
        assert_eq!(v.words(), [0xdcba_1234_56ab_cdef, 0x0f0f_0ffe]);
        assert_eq!(unpack(v.words(), 24, 4), f);
        assert_eq!(unpack(v.words(), 24, 2)[2..], [0; MAX_LANES - 2]);
    }

    /// A word of four lanes at `{y, x / 4}`: reads and writes only the lanes enabled, each
    /// at its own pixel, on a screen whose width is not a multiple of four.
    #[test]
    fn lanes_read_and_write_their_own_pixels() {
        let mut mem = Memory::new(4, 4, (6, 3), 100, [1, 2, 3], ReadDuringWrite::Old);
        mem.depth[2 * 6 + 5] = 55;
        let addr = (2 << 2) | 1; // row 2, pixels 4..7
        let mut req = Request { rd_en: 0b0010, rd_addr: addr, wr_en: 0b0001, wr_addr: addr, ..Request::default() };
        req.wr_z[0] = 7;
        req.wr_rgb[0] = 0x0a0b0c;
        req.wr_z[1] = 9;
        let w = mem.edge(true, &req);
        assert_eq!(w.as_slice(), [Write { x: 4, y: 2, z: 7, rgb: [10, 11, 12] }]);
        assert_eq!((mem.rd_z()[1], mem.reads, mem.writes), (55, 1, 1));
        assert_eq!((mem.depth[2 * 6 + 4], mem.depth[2 * 6 + 5]), (7, 55), "lane 1 not written");
        assert_eq!(mem.rd_z_value(16).words()[0], 55 << 16);
        assert!(mem.edge(false, &Request { wr_en: 0b10, ..req }).as_slice().is_empty(), "no write when not ready");
    }
}
