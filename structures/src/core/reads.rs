//! Container reads, traced and counted for teaching and for the report's "reads per query"
//! (`topolab explain NAME --trace OP`, the report's reads table), without touching the timed
//! code.
//!
//! Every read a structure's query code makes from one of its containers is written through
//! `read!` (`read!("O", o, he)` reads `o[he]`) or, where an iterator or a
//! library call reads for it (a scan with `iter()`, a binary search), announced right after
//! with `traced!`. Both are macros whose expansion depends on the cargo
//! feature `count-reads` of the crate they expand in:
//!
//! - without it (every build the lab times: `topolab`, the benches), `read!(name, s, i)` is
//!   `s[i]` and `traced!(..)` is nothing, token for token what the code wrote before;
//! - with it, each read is also reported to a sink of this thread ([`record`]), which
//!   [`trace`] and [`count`] open around one query.
//!
//! The `count-reads` build is the crate `topolab-structures-counted` (`structures/counted/`):
//! the same source files compiled a second time with the feature, a package of its own so that
//! cargo never unifies the feature into the timed `topolab-structures`, whichever packages one
//! build selects. The `topolab` binary links both: it times the one and traces the other.
//!
//! What counts as one read: one element of a container (an id of an index array, one
//! position, one record of a record structure such as the winged-edge's `E[e]`, one field
//! of a pointer structure's record, reached through its pointer). Arithmetic on ids (the
//! CHE's `next`, the index half-edge's `h ^ 1`, a grid's rows and columns) reads nothing;
//! the grids announce theirs with `computed!`, which a trace prints and
//! the count leaves out.

use crate::core::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use glam::DVec3;
use std::cell::RefCell;

/// `true` in the build that reports its reads (the crate `topolab-structures-counted`).
pub const ENABLED: bool = cfg!(feature = "count-reads");

/// A value read, as a trace prints it.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Value {
    /// An id or index (`u32`).
    Id(u32),
    /// The "none" of a link array (`u32::MAX`, the lecture's `N`).
    None,
    /// A signed entry (the CHE's `O[]` and `VH[]`: negative on the boundary).
    Signed(i64),
    /// Coordinates.
    Point([f64; 3]),
    /// A whole record: its fields' names and ids (`u32::MAX` for none).
    Record(&'static [&'static str], [u32; 8]),
}

impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Value::Id(x) => write!(f, "{x}"),
            Value::None => write!(f, "N"),
            Value::Signed(x) => write!(f, "{x}"),
            Value::Point([x, y, z]) => write!(f, "({x:.3}, {y:.3}, {z:.3})"),
            Value::Record(names, ids) => {
                write!(f, "{{")?;
                for (i, (name, id)) in names.iter().zip(ids).enumerate() {
                    let sep = if i == 0 { "" } else { ", " };
                    match id {
                        u32::MAX => write!(f, "{sep}{name}: N")?,
                        id => write!(f, "{sep}{name}: {id}")?,
                    }
                }
                write!(f, "}}")
            }
        }
    }
}

/// What a container element turns into in a trace.
pub trait Traced {
    /// The value as a trace prints it.
    fn traced(&self) -> Value;
}

impl Traced for u32 {
    fn traced(&self) -> Value {
        if *self == u32::MAX {
            Value::None
        } else {
            Value::Id(*self)
        }
    }
}
impl Traced for i32 {
    fn traced(&self) -> Value {
        Value::Signed(*self as i64)
    }
}
impl Traced for usize {
    fn traced(&self) -> Value {
        Value::Signed(*self as i64)
    }
}
impl Traced for DVec3 {
    fn traced(&self) -> Value {
        Value::Point(self.to_array())
    }
}
macro_rules! traced_id {
    ($($t:ty),*) => {$(
        impl Traced for $t {
            fn traced(&self) -> Value {
                self.0.traced()
            }
        }
    )*};
}
traced_id!(VertexId, EdgeId, FaceId, HalfEdgeId);

/// One event of a trace.
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    /// `container[index] = value` was read.
    Read {
        /// The container, as the structure's source names it (`O`, `next`, `edge_start`).
        container: &'static str,
        /// The element read.
        index: u64,
        /// What it held.
        value: Value,
    },
    /// Arithmetic that stands where other structures read (the grids): `what = value`.
    Computed {
        /// What was computed, in the grid's terms (`row`, `column`, `neighbour`).
        what: &'static str,
        /// Its value.
        value: i64,
    },
}

/// What the sink of this thread does with reads.
enum Sink {
    /// Keeps every event ([`trace`]).
    Trace(Vec<Event>),
    /// Counts reads only ([`count`]): cheap enough for scans of a million elements.
    Count(u64),
}

thread_local! {
    static SINK: RefCell<Option<Sink>> = const { RefCell::new(None) };
}

/// Reports a read to the sink of this thread, if one is open. Called by `read!`
/// and `traced!` in the `count-reads` build only.
#[inline(never)]
pub fn record(container: &'static str, index: u64, value: &dyn Traced) {
    SINK.with(|s| match &mut *s.borrow_mut() {
        Some(Sink::Trace(events)) => events.push(Event::Read {
            container,
            index,
            value: value.traced(),
        }),
        Some(Sink::Count(n)) => *n += 1,
        None => {}
    });
}

/// Reports arithmetic to a trace (not counted). Called by `computed!` in the
/// `count-reads` build only.
#[inline(never)]
pub fn record_computed(what: &'static str, value: i64) {
    SINK.with(|s| {
        if let Some(Sink::Trace(events)) = &mut *s.borrow_mut() {
            events.push(Event::Computed { what, value });
        }
    });
}

/// Opens `sink` around `f` and returns what it collected (the previous sink is restored, so a
/// panic inside `f` is the caller's; nesting is not supported and replaced).
fn with_sink<R>(sink: Sink, f: impl FnOnce() -> R) -> (R, Sink) {
    let before = SINK.with(|s| s.borrow_mut().replace(sink));
    let r = f();
    let sink = SINK.with(|s| std::mem::replace(&mut *s.borrow_mut(), before));
    (r, sink.expect("the sink opened here is still there"))
}

/// Runs `f` and returns every read (and grid arithmetic) it made, in order. Empty unless
/// [`ENABLED`].
pub fn trace<R>(f: impl FnOnce() -> R) -> (R, Vec<Event>) {
    match with_sink(Sink::Trace(Vec::new()), f) {
        (r, Sink::Trace(events)) => (r, events),
        (r, Sink::Count(_)) => (r, Vec::new()),
    }
}

/// Runs `f` and returns the number of container reads it made. Zero unless [`ENABLED`].
pub fn count<R>(f: impl FnOnce() -> R) -> (R, u64) {
    match with_sink(Sink::Count(0), f) {
        (r, Sink::Count(n)) => (r, n),
        (r, Sink::Trace(events)) => (r, events.len() as u64),
    }
}

/// `read!("name", container, index)`: `container[index]`, reported as a read of `name` in the
/// `count-reads` build (see the module docs). The element type must be `Copy` and
/// [`Traced`].
macro_rules! read {
    ($name:expr, $container:expr, $index:expr) => {{
        #[cfg(feature = "count-reads")]
        {
            let i = $index;
            let x = $container[i];
            $crate::core::reads::record($name, i as u64, &x);
            x
        }
        #[cfg(not(feature = "count-reads"))]
        {
            $container[$index]
        }
    }};
}

/// `traced!("name", index, value)`: announces a read the code just made some other way (an
/// iterator, a binary search, a pointer); nothing outside the `count-reads` build.
macro_rules! traced {
    ($name:expr, $index:expr, $value:expr) => {
        #[cfg(feature = "count-reads")]
        $crate::core::reads::record($name, ($index) as u64, &$value);
    };
}

/// `computed!("what", value)`: arithmetic a grid does where others read, for traces only;
/// nothing outside the `count-reads` build.
macro_rules! computed {
    ($what:expr, $value:expr) => {
        #[cfg(feature = "count-reads")]
        $crate::core::reads::record_computed($what, ($value) as i64);
    };
}

pub(crate) use {computed, read, traced};

/// The elements of `slice`, which starts at index `first` of the container `name`, each
/// announced as a read in the `count-reads` build; `slice.iter().copied()` otherwise.
#[inline(always)]
pub(crate) fn each<'a, T: Copy + Traced + 'a>(
    name: &'static str,
    slice: &'a [T],
    first: usize,
) -> impl Iterator<Item = T> + 'a {
    #[cfg(not(feature = "count-reads"))]
    {
        let _ = (name, first);
        slice.iter().copied()
    }
    #[cfg(feature = "count-reads")]
    {
        slice.iter().enumerate().map(move |(i, &x)| {
            record(name, (first + i) as u64, &x);
            x
        })
    }
}

/// Announces the reads of a scan of `slice` (which starts at index `first` of the container
/// `name`) that the code makes some other way (a `contains`, a library call): one read per
/// element in the `count-reads` build; nothing otherwise.
#[inline(always)]
pub(crate) fn scanned<T: Copy + Traced>(name: &'static str, slice: &[T], first: usize) {
    #[cfg(feature = "count-reads")]
    for (i, x) in slice.iter().enumerate() {
        record(name, (first + i) as u64, x);
    }
    #[cfg(not(feature = "count-reads"))]
    let _ = (name, slice, first);
}

// Tested through the counting build: `topolab-harness`'s `reads` tests trace and count every
// structure (this crate's own tests are built without `count-reads`).
