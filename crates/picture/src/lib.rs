//! Pictures of a `ccd-exact` query, from its [`ccd_scene::Scene`] and [`ccd_timeline::Outcome`]:
//!
//! - [`svg`]: the timeline as a strip over the span (separate / touch /
//!   overlap coloured, undecided gaps grey, each contact marked with its
//!   enclosure, the first contact labelled) and, for each contact, the two
//!   ellipsoids at that instant cut by the plane through the contact point
//!   perpendicular to the coordinate axis along which the normal has its
//!   smallest component (so the normal lies nearly in the picture), with
//!   their outlines projected on that plane, the point and the normal drawn;
//! - [`html`]: a self-contained page (no network at view time: its script is
//!   inline, a 2D canvas, no library) that animates the two bodies over the
//!   span with a time slider, colours them by state and marks the contacts.
//!
//! Positions are evaluated in `f64` ([`pose`]), for drawing only: the
//! enclosures written on the pictures are the outcome's exact ones.
//!
//! ```
//! use ccd_picture::{pose::poses, svg};
//! use ccd_scene::Scene;
//! use ccd_timeline::{Instant, Outcome, Segment, State, Stats};
//! use ccd_arith::Rat;
//! let scene = Scene::from_toml("[a]\nradii = [1, 1, 1]\n[b]\nradii = [1, 1, 1]\n[b.motion]\nkind = \"static\"\ncenter = [3, 0, 0]").unwrap();
//! let outcome = Outcome {
//!     span: Scene::default_span(),
//!     collision_free: true,
//!     undecided: None,
//!     first_contact: None,
//!     contacts: vec![],
//!     timeline: vec![Segment { state: State::Separate, start: Instant::exact(Rat::zero()), end: Instant::exact(Rat::one()), certified: true }],
//!     gaps: vec![],
//!     complete: true,
//!     stats: Stats::default(),
//!     geometry: vec![],
//!     segment_geometry: vec![],
//! };
//! let picture = svg(&scene, &outcome, "two spheres");
//! assert!(picture.starts_with("<svg") && picture.contains("collision-free"));
//! assert_eq!(poses(&scene, 0.5)[1].center, [3.0, 0.0, 0.0]);
//! ```

#![warn(missing_docs)]

mod html;
pub mod pose;
mod svg;

pub use html::html;
pub use svg::svg;

use ccd_timeline::State;

/// Fill colour of body A (RGB), in both pictures.
pub const COLOR_A: [u8; 3] = [0x3b, 0x6f, 0xd6];
/// Fill colour of body B (RGB), in both pictures.
pub const COLOR_B: [u8; 3] = [0x2c, 0xa2, 0x5f];

/// The colour of a state on the timeline strip (and of the bodies' outline
/// in the HTML page), as `#rrggbb`.
pub fn state_color(state: State) -> &'static str {
    match state {
        State::Separate => "#c6dbef",
        State::Touch => "#f28e2b",
        State::Overlap => "#d62728",
    }
}

/// The colour of an undecided gap.
pub const GAP_COLOR: &str = "#bdbdbd";

/// `#rrggbb` of an RGB triple.
pub fn hex(rgb: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2])
}

/// `text` with `&`, `<`, `>` and `"` escaped, for XML and HTML.
pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
