//! The links between the scanline units of one build, each declared once (`crate::link!`,
//! `crate::bundle!`), at the build's widths (`super::widths`).

use super::cull_sort::{COLOR, INV_W, OUTCODE, XY, Z};
use super::widths::{ADDR, CHANNEL, C_ACC, DC, DEPTH, DZ, EDGE_D, EDGE_Q, PIXEL, RGB, SCREEN, Z_ACC};
use rust_hdl::prelude::*;

crate::bundle! {
    /// `pixel_out`'s memory port, as `pixel_out` (and `raster_top` with it) holds it: a word
    /// per chunk of `LANES` pixels of a row (pixel x in lane x mod `LANES`) at address
    /// `{y, x / LANES}` (`AW` bits), each lane a depth (`ZW` = `LANES` depths: lane i at bits
    /// [i DEPTH, (i + 1) DEPTH)) and a colour (`CW` = `LANES` x 24 bits: lane i's
    /// `{R, G, B}`, R on top, at [i RGB, (i + 1) RGB)), read and written with an enable per
    /// lane (see `rtl::pixel_out`). One lane: [`MemoryPort`].
    ChunkPort<const LANES: usize, const AW: usize, const ZW: usize, const CW: usize> {
        /// The memory performs this cycle's read and write at the rising edge; low: neither.
        In ready: Bit,
        /// Read the depths of the lanes set at `rd_addr`.
        Out rd_en: Bits<LANES>,
        Out rd_addr: Bits<AW>,
        /// The depths last read (from the cycle after the read; a lane not read: any value).
        In rd_z: Bits<ZW>,
        /// Write the lanes set of `wr_z` and `wr_rgb` at `wr_addr`.
        Out wr_en: Bits<LANES>,
        Out wr_addr: Bits<AW>,
        Out wr_z: Bits<ZW>,
        Out wr_rgb: Bits<CW>,
    }
}

crate::bundle! {
    /// The SE back end's memory port (`raster_top` with `METHOD = 2`, `rtl::se_array`): a
    /// word of `EL` = 4 x engines lanes, lane 4 i + k the pixel 64 i + 4 j + k of a row for
    /// group j (engine i's port k), at address `{y, j}` (`AW` bits); a depth a lane (`ZW` =
    /// `EL` x `DEPTH` bits) and a colour (`CW` = `EL` x 24 bits, `{R, G, B}`). A read's data
    /// is wanted on `rd_z` in the cycle it is asked for (the engines' old-z load, 000 Fig. 6);
    /// a write is made at the rising edge, the lanes of `wr_en`.
    SeMemory<const EL: usize, const AW: usize, const ZW: usize, const CW: usize> {
        Out rd: Bit,
        Out rd_addr: Bits<AW>,
        In rd_z: Bits<ZW>,
        Out wr: Bit,
        Out wr_addr: Bits<AW>,
        Out wr_en: Bits<EL>,
        Out wr_z: Bits<ZW>,
        Out wr_rgb: Bits<CW>,
    }
}

/// The memory port of one lane: a word per pixel at address `{y, x}`, a depth and a
/// colour (`{R, G, B}`, R in the top byte), as the scanline `raster_top` has it.
pub type MemoryPort = ChunkPort<1, ADDR, DEPTH, RGB>;

crate::bundle! {
    /// The blending `pixel_out`'s memory port (`BLEND` = 1, `rtl::pixel_out::PixelOutBlend`):
    /// [`MemoryPort`] whose reads also return the word's colour, on `rd_rgb`, for the blend
    /// onto it. The same words, addresses and timing.
    BlendMemoryPort {
        /// The memory performs this cycle's read and write at the rising edge; low: neither.
        In ready: Bit,
        /// Read the word at `rd_addr`, `{y, x}` (one lane's enable, as `MemoryPort`'s).
        Out rd_en: Bits<1>,
        Out rd_addr: Bits<ADDR>,
        /// The depth and the colour (`{R, G, B}`, R on top) last read, from the cycle after
        /// the read.
        In rd_z: Bits<DEPTH>,
        In rd_rgb: Bits<RGB>,
        /// Write `wr_z` and `wr_rgb` at `wr_addr`.
        Out wr_en: Bits<1>,
        Out wr_addr: Bits<ADDR>,
        Out wr_z: Bits<DEPTH>,
        Out wr_rgb: Bits<RGB>,
    }
}

/// Declares an AXI4 read master's address (AR) and data (R) channels with `$data`-bit data
/// as a bundle (the ports `ar_valid`, `ar_ready`, `ar_addr`, `ar_len`, `ar_size`,
/// `ar_burst`, `r_valid`, `r_ready`, `r_data`, `r_resp`).
macro_rules! read_master {
    ($(#[$meta:meta])* $name:ident, $data:literal) => {
        crate::bundle! {
            $(#[$meta])*
            $name {
                Out ar_valid: Bit,
                In ar_ready: Bit,
                Out ar_addr: Bits<32>,
                Out ar_len: Bits<8>,
                Out ar_size: Bits<3>,
                Out ar_burst: Bits<2>,
                In r_valid: Bit,
                Out r_ready: Bit,
                In r_data: Bits<$data>,
                In r_resp: Bits<2>,
            }
        }
    };
}

read_master! {
    /// An AXI4 read master's address (AR) and data (R) channels, 128-bit data: the command
    /// parser reads its vertex buffer through it. Bursts are INCR (`ar_burst` 1) of 16-byte
    /// beats (`ar_size` 4), `ar_len + 1` beats; `r_ready` is always high. A beat answered
    /// with RRESP other than OKAY stops the parser (`Fault::Bus`).
    ReadMaster, 128
}

read_master! {
    /// An AXI4 read master's AR and R channels, 32-bit data, single-beat reads (`ar_len` 0,
    /// `ar_size` 2, `ar_burst` INCR); `r_ready` is always high: `pixel_bus` reads depth
    /// words through it.
    WordReadMaster, 32
}

crate::bundle! {
    /// An AXI4 write master's address (AW), data (W) and response (B) channels, 32-bit
    /// data, single-beat writes of every byte (`aw_len` 0, `aw_size` 2, `aw_burst` INCR,
    /// `w_strb` 15, `w_last` 1); `b_ready` is always high: `pixel_bus` writes depth and
    /// colour words through two of them.
    WordWriteMaster {
        Out aw_valid: Bit,
        In aw_ready: Bit,
        Out aw_addr: Bits<32>,
        Out aw_len: Bits<8>,
        Out aw_size: Bits<3>,
        Out aw_burst: Bits<2>,
        Out w_valid: Bit,
        In w_ready: Bit,
        Out w_data: Bits<32>,
        Out w_strb: Bits<4>,
        Out w_last: Bit,
        In b_valid: Bit,
        Out b_ready: Bit,
        In b_resp: Bits<2>,
    }
}

// LiteSlave's address ports are the register map's width.
const _: () = assert!(model::gpu_regs::ADDR_BITS == 6, "LiteSlave's addresses");

crate::bundle! {
    /// An AXI4-Lite slave, 32-bit data, byte addresses of `model::gpu_regs::ADDR_BITS` bits
    /// (no AWPROT or ARPROT): the host's port into `gpu_regs`.
    LiteSlave {
        In aw_valid: Bit,
        Out aw_ready: Bit,
        In aw_addr: Bits<6>,
        In w_valid: Bit,
        Out w_ready: Bit,
        In w_data: Bits<32>,
        In w_strb: Bits<4>,
        Out b_valid: Bit,
        In b_ready: Bit,
        Out b_resp: Bits<2>,
        In ar_valid: Bit,
        Out ar_ready: Bit,
        In ar_addr: Bits<6>,
        Out r_valid: Bit,
        In r_ready: Bit,
        Out r_data: Bits<32>,
        Out r_resp: Bits<2>,
    }
}

crate::bundle! {
    /// A triangle leaves `cull_sort`, passed or rejected, and why (`rtl::cull_sort`).
    Verdict {
        /// High in the cycle the triangle leaves.
        Out valid: Bit,
        /// `rtl::cull_sort::verdict`: 0 passed, 1 outside, 2 back face, 3 zero area.
        Out code: Bits<2>,
        /// For `OUTSIDE`, the planes all three vertices are outside of (`rtl::cull_sort::plane`).
        Out outside: Bits<OUTCODE>,
    }
}

/// Declares a link whose fields are a pixel's (`model::span::Pixel`: `x`, `y`, `z`, `rgb0..2`),
/// then the fields given.
macro_rules! pixel_link {
    ($(#[$meta:meta])* $source:ident => $sink:ident { $($more:tt)* }) => {
        crate::link! {
            $(#[$meta])*
            $source => $sink {
                x: Bits<SCREEN>,
                y: Bits<SCREEN>,
                /// Depth, the depth buffer's `DEPTH` bits.
                z: Bits<DEPTH>,
                /// R, G, B.
                rgb0: Bits<CHANNEL>,
                rgb1: Bits<CHANNEL>,
                rgb2: Bits<CHANNEL>,
                $($more)*
            }
        }
    };
}

pixel_link! {
    /// A pixel on screen (`model::span::Pixel`): `span` -> `pixel_out`, and the fragments
    /// out of a `raster_top` without `pixel_out`.
    PixelSource => PixelSink {}
}

pixel_link! {
    /// A pixel to blend (`model::span::Pixel` with the arguments of
    /// `model::pixel_out::Framebuffer::pixel_out_blended`): into the blending `pixel_out`
    /// (`BLEND` = 1).
    BlendPixelSource => BlendPixelSink {
        /// The fragment's alpha (0..=255 for 0..1).
        alpha: Bits<8>,
        /// The blend mode, `rtl::blend`'s code (`model::blend::MODES`' index; 6 and 7 opaque).
        mode: Bits<3>,
    }
}

crate::link! {
    /// One scanline's span (`model::edge_walk::SpanCmd`): `edge_walk` -> the span FIFO ->
    /// `span`.
    SpanCmdSource => SpanCmdSink {
        /// The scanline.
        y: Bits<SCREEN>,
        /// First and last pixel inside (xl <= xr), `PIXEL` bits two's complement, possibly
        /// off screen: `span` clips x.
        xl: Bits<PIXEL>,
        xr: Bits<PIXEL>,
        /// Attributes at pixels xl and xr (`z_acc`, `c_acc`).
        left_z: Bits<Z_ACC>,
        left_c0: Bits<C_ACC>,
        left_c1: Bits<C_ACC>,
        left_c2: Bits<C_ACC>,
        right_z: Bits<Z_ACC>,
        right_c0: Bits<C_ACC>,
        right_c1: Bits<C_ACC>,
        right_c2: Bits<C_ACC>,
        /// Per-pixel steps (`dz`, `dc`).
        ddx_z: Bits<DZ>,
        ddx_c0: Bits<DC>,
        ddx_c1: Bits<DC>,
        ddx_c2: Bits<DC>,
    }
}

crate::link! {
    /// A set-up triangle (`model::triangle_setup::TriangleSetupOut` without `divisions`):
    /// `triangle_setup` -> `edge_walk`. Each field is the low bits of the model's value:
    /// `count` reaches 2^(PIXEL-1) = 4096 (a triangle over the whole `xy` range): read it
    /// unsigned.
    TriangleSetupSource => TriangleSetupSink {
        /// `TriangleSetupOut::walk`: high for `Walk::Up`.
        walk: Bit,
        maj_left: Bit,
        /// The long edge (`maj`): the exact edge walker (`j`, `count`, `x`, `r`, `q`, `rho`, `d`), the
        /// attributes at its first scanline (`at`) and their steps (`inc0`, `inc1`).
        maj_j: Bits<PIXEL>,
        maj_count: Bits<PIXEL>,
        maj_x: Bits<PIXEL>,
        maj_r: Bits<EDGE_D>,
        maj_q: Bits<EDGE_Q>,
        maj_rho: Bits<EDGE_D>,
        maj_d: Bits<EDGE_D>,
        maj_at_z: Bits<Z_ACC>,
        maj_at_c0: Bits<C_ACC>,
        maj_at_c1: Bits<C_ACC>,
        maj_at_c2: Bits<C_ACC>,
        maj_inc0_z: Bits<DZ>,
        maj_inc0_c0: Bits<DC>,
        maj_inc0_c1: Bits<DC>,
        maj_inc0_c2: Bits<DC>,
        maj_inc1_z: Bits<DZ>,
        maj_inc1_c0: Bits<DC>,
        maj_inc1_c1: Bits<DC>,
        maj_inc1_c2: Bits<DC>,
        /// The short edges, in walk order (`short[0]`).
        short0_j: Bits<PIXEL>,
        short0_count: Bits<PIXEL>,
        short0_x: Bits<PIXEL>,
        short0_r: Bits<EDGE_D>,
        short0_q: Bits<EDGE_Q>,
        short0_rho: Bits<EDGE_D>,
        short0_d: Bits<EDGE_D>,
        short0_at_z: Bits<Z_ACC>,
        short0_at_c0: Bits<C_ACC>,
        short0_at_c1: Bits<C_ACC>,
        short0_at_c2: Bits<C_ACC>,
        short0_inc0_z: Bits<DZ>,
        short0_inc0_c0: Bits<DC>,
        short0_inc0_c1: Bits<DC>,
        short0_inc0_c2: Bits<DC>,
        short0_inc1_z: Bits<DZ>,
        short0_inc1_c0: Bits<DC>,
        short0_inc1_c1: Bits<DC>,
        short0_inc1_c2: Bits<DC>,
        /// (`short[1]`).
        short1_j: Bits<PIXEL>,
        short1_count: Bits<PIXEL>,
        short1_x: Bits<PIXEL>,
        short1_r: Bits<EDGE_D>,
        short1_q: Bits<EDGE_Q>,
        short1_rho: Bits<EDGE_D>,
        short1_d: Bits<EDGE_D>,
        short1_at_z: Bits<Z_ACC>,
        short1_at_c0: Bits<C_ACC>,
        short1_at_c1: Bits<C_ACC>,
        short1_at_c2: Bits<C_ACC>,
        short1_inc0_z: Bits<DZ>,
        short1_inc0_c0: Bits<DC>,
        short1_inc0_c1: Bits<DC>,
        short1_inc0_c2: Bits<DC>,
        short1_inc1_z: Bits<DZ>,
        short1_inc1_c0: Bits<DC>,
        short1_inc1_c1: Bits<DC>,
        short1_inc1_c2: Bits<DC>,
        /// Per-pixel steps of z (`dz`) and R, G, B (`dc`).
        ddx_z: Bits<DZ>,
        ddx_c0: Bits<DC>,
        ddx_c1: Bits<DC>,
        ddx_c2: Bits<DC>,
    }
}

/// Declares a link whose fields are a triangle's three vertices (`[model::input::Vtx; 3]`:
/// `v<k>_x`, `v<k>_y`, `v<k>_z`, `v<k>_c0..2`, `v<k>_iw`), then the fields given.
macro_rules! triangle_link {
    ($(#[$meta:meta])* $source:ident => $sink:ident { $($more:tt)* }) => {
        crate::link! {
            $(#[$meta])*
            $source => $sink {
                /// Vertex 0: `xy`, `z`, `color`, `inv_w` raw values (`model::input::Vtx`).
                v0_x: Bits<XY>,
                v0_y: Bits<XY>,
                v0_z: Bits<Z>,
                v0_c0: Bits<COLOR>,
                v0_c1: Bits<COLOR>,
                v0_c2: Bits<COLOR>,
                v0_iw: Bits<INV_W>,
                /// Vertex 1.
                v1_x: Bits<XY>,
                v1_y: Bits<XY>,
                v1_z: Bits<Z>,
                v1_c0: Bits<COLOR>,
                v1_c1: Bits<COLOR>,
                v1_c2: Bits<COLOR>,
                v1_iw: Bits<INV_W>,
                /// Vertex 2.
                v2_x: Bits<XY>,
                v2_y: Bits<XY>,
                v2_z: Bits<Z>,
                v2_c0: Bits<COLOR>,
                v2_c1: Bits<COLOR>,
                v2_c2: Bits<COLOR>,
                v2_iw: Bits<INV_W>,
                $($more)*
            }
        }
    };
}

triangle_link! {
    /// A triangle as submitted (`[model::input::Vtx; 3]`): into `cull_sort`, and into
    /// `raster_top` with `cull_sort`.
    TriangleSource => TriangleSink {}
}

triangle_link! {
    /// A triangle sorted by y with the clip planes it crosses (`model::cull_sort::Sorted`):
    /// `cull_sort` -> `triangle_setup`, and into `raster_top` without `cull_sort`. (Setup
    /// does not read `inv_w`: it is the vector method's.)
    SortedSource => SortedSink {
        /// OR of the three outcodes: the planes the triangle crosses (`Sorted::crosses`).
        crosses: Bits<OUTCODE>,
    }
}

triangle_link! {
    /// A triangle out of `command_parser` (`model::command_parser::Triangle`): into the
    /// rasterizer, with TI's end flags.
    ParsedSource => ParsedSink {
        /// The buffer's last triangle.
        end_of_buffer: Bit,
        /// The frame's last triangle.
        end_of_frame: Bit,
    }
}
