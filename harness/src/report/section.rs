//! What a section of the report is: its name (`--sections`, `results.json`'s
//! `settings.sections`), what it needs measured before it ([`Needs`]), the phase its own
//! measurement is timed as, and its HTML. The page, the selection of a run and the run's
//! phases all follow the one list of [`crate::report::sections::SECTIONS`].

use crate::measuring::phases::Phase;
use crate::page::plot::{self, Style};
use crate::report::run::{ReportError, Run};
use crate::results::Results;

/// How much of the size sweep (every structure on the generated tori and grids) a section
/// needs.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum SizeSweep {
    /// None: the generated meshes are not measured.
    None,
    /// Construction and the vertex 1-ring sweep (memory and construction sections).
    Light,
    /// Every operator, kernel and workload.
    Full,
}

/// What a section needs of the real meshes (`bench-data/cache/`).
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Real {
    /// Nothing.
    None,
    /// Read (and repaired where refused), not measured: for their thumbnails.
    Read,
    /// Read and measured (construction and the vertex 1-ring sweep).
    Measured,
}

/// What a section needs of the refined real meshes (family
/// [`FAMILY`](crate::report::sections::real_at_scale::FAMILY)).
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Refined {
    /// Nothing.
    None,
    /// Made, not measured: the element-order section renumbers the smallest.
    Made,
    /// Made and measured like the tori.
    Measured,
}

/// What a section needs from the run before it is drawn, besides its own measurement.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Needs {
    /// What of the size sweep it is drawn from.
    pub size_sweep: SizeSweep,
    /// The generated meshes made, measured or not (the section measures on them itself).
    pub generated: bool,
    /// The real meshes.
    pub real: Real,
    /// The refined real meshes.
    pub refined: Refined,
    /// A name `--structures` must list for the section to run (it measures that subject
    /// alone, and takes long): `None` for every other section.
    pub subject: Option<&'static str>,
}

impl Needs {
    /// Nothing measured before the section.
    pub const NOTHING: Needs = Needs {
        size_sweep: SizeSweep::None,
        generated: false,
        real: Real::None,
        refined: Refined::None,
        subject: None,
    };

    /// The size sweep `s`, nothing else.
    pub const fn size_sweep(s: SizeSweep) -> Needs {
        Needs {
            size_sweep: s,
            ..Needs::NOTHING
        }
    }

    /// The generated meshes, not measured by the size sweep.
    pub const GENERATED: Needs = Needs {
        generated: true,
        ..Needs::NOTHING
    };
}

/// What every section draws from: the results and, in the order of the run, the structures'
/// names and plot styles.
pub struct Page<'a> {
    /// The run's results.
    pub r: &'a Results,
    /// The structures measured, in the order of the run.
    pub names: Vec<&'a str>,
    styles: Vec<Style>,
}

impl<'a> Page<'a> {
    /// The page of `r`: one plot style per structure, by its family.
    pub fn new(r: &'a Results) -> Self {
        let names: Vec<&str> = r.structures.iter().map(|s| s.name.as_str()).collect();
        let styles = plot::styles(&r.structures.iter().map(|s| s.family).collect::<Vec<_>>());
        Self { r, names, styles }
    }

    /// The plot style of the structure called `name` (the first one's for a name not run).
    pub fn style(&self, name: &str) -> Style {
        let i = self.names.iter().position(|&n| n == name).unwrap_or(0);
        self.styles[i]
    }
}

/// One section of the report page.
pub trait Section: Sync {
    /// Its kebab-case name: `--sections` and `results.json`'s `settings.sections`.
    fn name(&self) -> &'static str;

    /// What it needs measured before it: nothing, by default.
    fn needs(&self) -> Needs {
        Needs::NOTHING
    }

    /// The phase its own measurement is timed as, when it measures something of its own.
    fn phase(&self) -> Option<Phase> {
        None
    }

    /// Its own measurement, after the size sweep, the fits and the limits, timed as its
    /// [`phase`](Section::phase): it adds its rows to `run.results`. Nothing, by default.
    fn measure(&self, run: &mut Run) -> Result<(), ReportError> {
        let _ = run;
        Ok(())
    }

    /// Whether it is drawn above the Machine block (what a reader wants before the details):
    /// `false`, by default.
    fn before_machine(&self) -> bool {
        false
    }

    /// Draws it.
    fn render(&self, h: &mut String, page: &Page);
}
