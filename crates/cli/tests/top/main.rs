//! Integration tests of `kreisel top`, run through the real binary: the
//! report against the library's answers, the text format, the sleeping top,
//! the SVG and PNG figures, and one-line errors for bad arguments.

mod degrees;
mod errors;
mod limits;
mod plots;
mod report;
mod series;
mod support;
