//! The testbenches' first test binary (see its Cargo.toml): the scanline units, `raster_top`,
//! the command parser and `gpu_top`, one module per unit, plus the harness's own tests. The
//! back ends are in `back_ends.rs`.

mod command_parser;
mod cull_sort;
mod divider;
mod edge_walk;
mod ept;
mod gpu_regs;
mod gpu_top;
mod harness;
mod pixel_bus;
mod pixel_out;
mod pixel_out_blend;
mod raster_top;
mod span;
mod triangle_queue;
mod triangle_setup;
