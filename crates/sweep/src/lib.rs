//! `edgepaint sweep`: speed against accuracy over methods and number formats.
//!
//! A sweep runs every (scene, method, design point) of a [`grid::Grid`] through the
//! bit-exact models and the float reference (`accuracy::compare`) and writes one
//! [`row::Row`] per point: the design (every quantity's format, the method's parameters),
//! its accuracy (PSNR, colour and depth error in LSBs, coverage and depth-order
//! differences, triangles not drawn), its speed (cycles per frame from `model::cycles`,
//! pixels per clock, frame time at the clock of [`clock`]'s model) and its cost ([`area`]'s
//! model, fitted to Yosys runs of real builds), where the method's pipeline exists in RTL.
//! [`run::run`] spreads the points
//! over every core and caches each result, so that an interrupted sweep resumes and shards
//! run on other machines merge ([`store::merge`]).
//! [`chart::charts`] turns the rows into charts (error against cycles, frame time and area
//! with the Pareto front, one sensitivity chart per knob), [`chart::draw`] draws them as PNG
//! and SVG, and [`report::write`] writes a Markdown report that embeds them.
//! [`texture`] sweeps the texture unit (001 section II-5): its precision knobs and cache
//! geometries against conformance failures, area ([`texture_area`]), hit rate and frame time.

pub mod area;
pub mod chart;
pub mod clock;
pub mod grid;
pub mod report;
pub mod row;
pub mod run;
pub mod store;
pub mod texture;
pub mod texture_area;
