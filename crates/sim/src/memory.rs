//! The depth and colour buffers behind `pixel_out`'s memory port, in Rust (see
//! `rtl::pixel_out` for the port's contract): one word per pixel at address `{y, x}` (`x` in
//! the low `n` bits for size class `n`), reads returning data the cycle after, `mem$ready`
//! stalling both.

use crate::streams::unsigned;
use crate::Outputs;
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

/// One write the memory performed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Write {
    pub x: u32,
    pub y: u32,
    pub z: u32,
    pub rgb: [u8; 3],
}

/// The memory's request in one cycle, as `pixel_out` (or `raster_top`) drives it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Request {
    pub rd_en: bool,
    pub rd_addr: u32,
    pub wr_en: bool,
    pub wr_addr: u32,
    pub wr_z: u32,
    pub wr_rgb: u32,
}

impl Request {
    /// Read off a unit's outputs (`mem$rd_en`, ... `mem$wr_rgb`: `rtl::links::MemoryPort`).
    pub fn of(o: &Outputs) -> Request {
        let get = |p: &str| unsigned(o.get(p)) as u32;
        Request {
            rd_en: get("mem$rd_en") == 1,
            rd_addr: get("mem$rd_addr"),
            wr_en: get("mem$wr_en") == 1,
            wr_addr: get("mem$wr_addr"),
            wr_z: get("mem$wr_z"),
            wr_rgb: get("mem$wr_rgb"),
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
    /// Writes performed so far.
    pub writes: u64,
    /// Reads performed so far.
    pub reads: u64,
    /// Address bits of `x`: the size class.
    x_bits: u32,
    read_during_write: ReadDuringWrite,
    rd_z: u32,
}

impl Memory {
    /// Buffers cleared to depth `z_max` and colour `background`, for the `pixel_out` of size
    /// class `class`.
    pub fn new(class: u32, (width, height): (u32, u32), z_max: u32, background: [u8; 3], rdw: ReadDuringWrite) -> Self {
        let n = (width * height) as usize;
        Memory {
            width,
            height,
            x_bits: class,
            depth: vec![z_max; n],
            rgb: vec![background; n],
            written: vec![false; n],
            writes: 0,
            reads: 0,
            read_during_write: rdw,
            rd_z: 0,
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

    /// `rd_z`: the depth last read.
    pub fn rd_z(&self) -> u32 {
        self.rd_z
    }

    /// The pixel `(x, y)` at address `addr`.
    fn xy(&self, addr: u32) -> (u32, u32) {
        (addr & ((1 << self.x_bits) - 1), addr >> self.x_bits)
    }

    fn index(&self, addr: u32, what: &str) -> usize {
        let (x, y) = self.xy(addr);
        assert!(
            x < self.width && y < self.height,
            "{what} of ({x}, {y}), off the {}x{} screen",
            self.width,
            self.height
        );
        (y * self.width + x) as usize
    }

    /// One rising edge with `req` asked for: with `mem$ready` the memory performs the
    /// read and the write. Returns the write, if one was performed.
    pub fn edge(&mut self, mem_ready: bool, req: &Request) -> Option<Write> {
        if !mem_ready {
            return None;
        }
        let read = req.rd_en.then(|| self.index(req.rd_addr, "read"));
        if let (Some(i), ReadDuringWrite::Old) = (read, self.read_during_write) {
            self.rd_z = self.depth[i];
        }
        let write = req.wr_en.then(|| {
            let i = self.index(req.wr_addr, "write");
            let rgb = [req.wr_rgb >> (2 * CHANNEL), req.wr_rgb >> CHANNEL, req.wr_rgb].map(|c| c as u8);
            self.depth[i] = req.wr_z;
            self.rgb[i] = rgb;
            self.written[i] = true;
            self.writes += 1;
            let (x, y) = self.xy(req.wr_addr);
            Write { x, y, z: req.wr_z, rgb }
        });
        if let (Some(i), ReadDuringWrite::New) = (read, self.read_during_write) {
            self.rd_z = self.depth[i];
        }
        self.reads += read.is_some() as u64;
        write
    }
}

#[cfg(test)]
mod tests {
    use super::{Memory, ReadDuringWrite};
    use model::pixel_out::Framebuffer;

    #[test]
    fn differs_from_names_the_first_pixel_that_differs() {
        let mut fb = Framebuffer::new(4, 3, 100, [1, 2, 3]);
        let mut mem = Memory::new(2, (4, 3), 100, [1, 2, 3], ReadDuringWrite::Old);
        assert_eq!(mem.differs_from(&fb), None);
        fb.depth[2 * 4 + 1] = 7;
        assert_eq!(mem.differs_from(&fb).unwrap(), "depth of pixel (1, 2): RTL 100, model 7");
        mem.rgb[4 + 3] = [9, 9, 9];
        assert_eq!(mem.differs_from(&fb).unwrap(), "colour of pixel (3, 1): RTL [9, 9, 9], model [1, 2, 3]");
        let small = Framebuffer::new(2, 2, 100, [1, 2, 3]);
        assert_eq!(mem.differs_from(&small).unwrap(), "a 4x3 memory against a 2x2 frame");
    }
}
