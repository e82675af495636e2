//! The testbenches' second test binary (see its Cargo.toml): the back ends, one module per
//! unit: the texture path of paper 001 (its units, the path and the textured `raster_top`),
//! blending, the barycentric vector unit of 004 and the shading engine of 000.

mod blend;
mod raster_top_textured;
mod se;
mod se_cmd;
mod texture_address;
mod texture_cache;
mod texture_coords;
mod texture_filter;
mod texture_path;
mod texture_setup;
mod texture_unit;
mod vector;
