//! The testbenches' first test binary (see its Cargo.toml): the scanline units, `raster_top`,
//! the shading engine of 000 and its `se_cmd`, the command parser and `gpu_top`, one module per
//! unit, plus the harness's own tests. Texture, blending and the vector unit are in
//! `texture_vector.rs`.

mod command_parser;
mod cull_sort;
mod divider;
mod edge_walk;
mod ept;
mod gpu_regs;
mod gpu_top;
mod harness;
mod mul;
mod pixel_bus;
mod pixel_out;
mod pixel_out_blend;
mod raster_top;
mod se;
mod se_cmd;
mod span;
mod triangle_queue;
mod triangle_setup;
