//! Bit-exact fixed-point models of edgepaint's hardware units. Each unit module
//! mirrors the RTL unit of the same name in `crates/rtl` and is what its
//! simulations are checked against, bit for bit.
//!
//! * [`cull_sort`] (003), [`divider`] (001), [`triangle_setup`] (001),
//!   [`edge_walk`] (001, 003), [`span`] (001, 003), [`pixel_out`]: the scanline pipeline;
//! * [`vector`] (004): per-pixel barycentric rasterization;
//! * [`texture_unit`] (001): perspective-correct, mip-mapped, filtered texels and the texture
//!   environment, reading [`texture_memory`]'s layout;
//! * [`se`] (000): the shading engine, cycle-exact, and the engine array drawing the scanline's spans,
//!   fed by [`se_cmd`];
//! * [`render`]: whole frames through either, with analysis mode; [`cycles`]: the cycle model;
//! * [`raster_top`]: a frame as the scanline pipeline's RTL takes and writes it;
//! * [`guard_band`]: the host's clipping front end; [`input`]: float vertices to hardware words;
//!   [`ctx`]: formats and overflow records.

pub mod blend;
pub mod command_parser;
pub mod ctx;
pub mod cull_sort;
pub mod cycles;
pub mod divider;
pub mod edge_walk;
pub mod ept;
pub mod gpu_regs;
pub mod gpu_top;
pub mod guard_band;
pub mod input;
pub mod pixel_bus;
pub mod pixel_out;
pub mod raster_top;
pub mod read_memory;
pub mod render;
pub mod se;
pub mod se_cmd;
pub mod span;
pub mod texture_address;
pub mod texture_cache;
pub mod texture_coords;
pub mod texture_filter;
pub mod texture_memory;
pub mod texture_path;
pub mod texture_setup;
pub mod texture_unit;
pub mod triangle_queue;
pub mod triangle_setup;
pub mod vector;
pub mod vertex_buffer;
pub mod word_memory;

/// Seed for randomised tests: `EDGEPAINT_SEED`, default 1.
#[cfg(test)]
pub(crate) fn test_seed() -> u64 {
    std::env::var("EDGEPAINT_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1)
}

/// Case count for randomised tests: `EDGEPAINT_N`, default 1000.
#[cfg(test)]
pub(crate) fn test_count() -> usize {
    std::env::var("EDGEPAINT_N").ok().and_then(|s| s.parse().ok()).unwrap_or(1000)
}
