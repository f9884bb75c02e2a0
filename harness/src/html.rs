//! The self-contained HTML report (inline CSS and SVG, no network) drawn from
//! [`Results`](crate::results::Results): the page is [`crate::report::page`].

pub use crate::report::page::render;
