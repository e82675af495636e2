//! The testbenches' second test binary (see its Cargo.toml): the texture path of paper 001
//! (its units, the path and the textured `raster_top`), blending, and the barycentric vector
//! unit of 004, one module per unit.

mod blend;
mod raster_top_textured;
mod texture_address;
mod texture_cache;
mod texture_coords;
mod texture_filter;
mod texture_path;
mod texture_setup;
mod texture_unit;
mod vector;
