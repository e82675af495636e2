//! `edgepaint stability`: where each method and number format stops drawing correctly
//! (issue 15).
//!
//! Families of generated triangles ([`family`], their geometry in [`geometry`]) are swept
//! along one or two axes; every cell ([`cell`]) is drawn by a fixed-point method (scanline
//! 001/003, vector 004, the shading engines of 000) at a point of number formats and
//! compared with the float reference (`accuracy::compare`), and judged by its family's
//! documented criterion. [`run`] runs the cells in parallel, [`boundary`] finds where each
//! row of a map starts failing, [`map`] draws the heatmaps with the boundary, and
//! [`report`] writes `cells.json` and `report.md`. [`texture`] stresses the texture unit
//! (001 section II-5) the same way: its families through the bit-exact unit, judged by the
//! conformance check.

pub mod boundary;
pub mod cell;
pub mod family;
pub mod geometry;
pub mod map;
pub mod report;
pub mod run;
pub mod texture;
