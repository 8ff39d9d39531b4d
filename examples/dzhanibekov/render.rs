//! A small software 3-D renderer for the rigid-body demo.
//!
//! Everything happens on the CPU in plain safe Rust: an [`Image`] holds
//! `0x00RRGGBB` pixels (the format `minifb` expects, and easy to quantise for
//! a GIF), a [`Camera`] describes a perspective projection, and a
//! [`Renderer`] owns a depth buffer and draws z-buffered, flat-shaded
//! triangle meshes, thick depth-tested 3-D lines and arrows into a clip
//! rectangle (the 3-D panel of a larger frame).
//!
//! Conventions:
//!
//! * View coordinates: `x` right, `y` up, `z` toward the viewer
//!   (right-handed). The eye sits at view `(0, 0, distance)`.
//! * Screen coordinates: pixels, `x` right, `y` down; pixel `(i, j)` has its
//!   centre at `(i + 0.5, j + 0.5)`.
//! * A view-space point `p_v` maps to
//!   `x = cx + f·x_v / (distance − z_v)`, `y = cy − f·y_v / (distance − z_v)`,
//!   with `depth = distance − z_v`; geometry closer than [`NEAR_DEPTH`] is
//!   clipped away.
//! * Meshes are closed and wound counter-clockwise when seen from outside, so
//!   back faces (clockwise on screen as seen by the viewer) are culled.
//!
//! Rasterisation uses exact integer edge functions on vertices snapped to a
//! 1/256-pixel grid with a top-left fill rule, so triangles sharing an edge
//! leave no cracks and hit no pixel twice. The depth buffer stores `1/depth`,
//! which is affine in screen space and therefore interpolated exactly.
//!
//! Bad input never panics: triangles with non-finite or out-of-range
//! vertices, degenerate triangles, and geometry behind the camera or outside
//! the clip rectangle are skipped silently.
//!
//! Why hand-written and not on `tiny-skia` (which the workspace has, and
//! which draws the frame's 2-D part, the chart and the text, through
//! `kreisel_plot`): tiny-skia is a 2-D path rasteriser with no depth
//! buffer. The handle's principal axes run through the body and must be
//! hidden where they are inside or behind it and shown where they stick
//! out; with tiny-skia that needs triangles and segments sorted and split
//! by depth (painter's algorithm, wrong for this non-convex T), and its
//! anti-aliased fills leave seams along the edges that triangles share.
//! This renderer costs little: measured on the headless `--gif` run at the
//! default 640 × 320 (68 triangles, three axes, two arrows), the 3-D panel
//! takes about 0.2 ms a frame, the 2-D overlay through tiny-skia about 4 ms.
//!
//! Layout: [`Image`] and [`ClipRect`] live in `image`, [`Camera`] in
//! `camera`, [`Material`], [`Light`] and face shading in `shading`. The
//! [`Renderer`] struct and its frame/depth-buffer methods are in `renderer`;
//! its drawing methods are spread over `mesh` (triangle meshes), `lines`
//! (lines and arrows) and `raster` (the triangle rasteriser), with near-plane
//! clipping and projection of primitives in `clip`.

// The demo uses only part of the API; unused items must not fail
// `-D warnings` builds. (Lint levels set here apply to all submodules.)
#![allow(dead_code)]

// Explicit paths, so that the submodules are found however this file is
// reached: as `render.rs` of the example, or through `tests/dzhanibekov.rs`
// (a file loaded via `#[path]` looks for its submodules next to itself).
#[path = "render/camera.rs"]
mod camera;
#[path = "render/clip.rs"]
mod clip;
#[path = "render/image.rs"]
mod image;
#[path = "render/lines.rs"]
mod lines;
#[path = "render/mesh.rs"]
mod mesh;
#[path = "render/raster.rs"]
mod raster;
#[path = "render/renderer.rs"]
mod renderer;
#[path = "render/shading.rs"]
mod shading;
#[cfg(test)]
#[path = "render/test_util.rs"]
mod test_util;

// An including example may use only part of the API. `dead_code` does not
// cover imports; today every re-export is also used by a sibling module, but
// this keeps such builds clean if that changes.
#[allow(unused_imports)]
pub use self::{
    camera::{Camera, NEAR_DEPTH},
    image::{ClipRect, Image, channels, rgb},
    lines::LINE_DEPTH_BIAS,
    renderer::Renderer,
    shading::{Light, Material},
};
