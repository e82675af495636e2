//! The one test binary of the testbenches crate (see its Cargo.toml): one module per unit,
//! plus the harness's own tests.

mod blend;
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
mod raster_top_textured;
mod se;
mod se_cmd;
mod span;
mod texture_address;
mod texture_cache;
mod texture_coords;
mod texture_filter;
mod texture_path;
mod texture_setup;
mod texture_unit;
mod triangle_queue;
mod triangle_setup;
mod vector;
