//! What a `topolab report` run measures, from `--sections` and `--structures`: the sections
//! of the page it shows ([`Section`]), and of those the parts that take long on their own (the
//! libigl and hull sections) only when `--structures` names what they measure, so that a run
//! focused on a few structures stays quick.

use topolab_harness::sections::{self, Section, SizeSweep};

/// The name `--structures` accepts for libigl (an outside baseline, run from Python, not a
/// structure of the registry): the libigl section runs when the list names it.
pub const LIBIGL: &str = "libigl";

/// The structure the hull section's algorithms build on: the hull section runs when
/// `--structures` names it.
pub const HULL_STRUCTURE: &str = "winged-edge";

/// A section by name (`--sections`); an unknown one lists the known.
pub fn section(name: &str) -> Result<Section, String> {
    Section::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Section::ALL.iter().map(|s| s.name()).collect();
        format!("unknown section; known: {}", names.join(", "))
    })
}

/// What a run measures.
#[derive(Clone, Debug)]
pub struct Selection {
    /// The sections shown, in page order, each once.
    pub sections: Vec<Section>,
    /// What the size sweep measures on the generated meshes.
    pub size_sweep: SizeSweep,
    /// The real meshes are read (and repaired where refused): for their section or thumbnails.
    pub real_meshes: bool,
    /// The real meshes are measured.
    pub measure_real: bool,
    /// The generated meshes are made: for the size sweep, the element orders or thumbnails.
    pub generated: bool,
    /// The refined real meshes are made: for their section (which measures them) or the
    /// element-order section (which renumbers the smallest).
    pub refined: bool,
    /// The element-order section runs.
    pub orderings: bool,
    /// The libigl section runs.
    pub libigl: bool,
    /// The hull section runs.
    pub hull: bool,
    /// The changing workloads run (on the generated tori).
    pub changing: bool,
    /// The decimation section runs (on the generated tori).
    pub decimate: bool,
}

impl Selection {
    /// The selection of `--sections` (`None`: every section) and `--structures` (`None`:
    /// every structure, and libigl). Sections that `--structures` leaves without a subject are
    /// dropped with a note in `notes`.
    pub fn new(
        requested: Option<&[Section]>,
        structures: Option<&[String]>,
        notes: &mut Vec<String>,
    ) -> Self {
        let mut sections: Vec<Section> = requested.unwrap_or(&Section::ALL).to_vec();
        sections.sort_unstable();
        sections.dedup();
        let named = |n: &str| structures.is_none_or(|list| list.iter().any(|s| s == n));
        for (section, subject) in [(Section::Libigl, LIBIGL), (Section::Hull, HULL_STRUCTURE)] {
            if sections.contains(&section) && !named(subject) {
                sections.retain(|&s| s != section);
                notes.push(format!(
                    "The {} section was not run: --structures does not name {subject}.",
                    section.name()
                ));
            }
        }
        let shows = |s: Section| sections.contains(&s);
        let size_sweep = sections::size_sweep(&sections);
        Self {
            size_sweep,
            real_meshes: shows(Section::RealMeshes) || shows(Section::Meshes),
            measure_real: shows(Section::RealMeshes),
            generated: size_sweep != SizeSweep::None
                || shows(Section::Orderings)
                || shows(Section::Changing)
                || shows(Section::Decimate)
                || shows(Section::Meshes),
            refined: shows(Section::RealAtScale) || shows(Section::Orderings),
            orderings: shows(Section::Orderings),
            libigl: shows(Section::Libigl),
            hull: shows(Section::Hull),
            changing: shows(Section::Changing),
            decimate: shows(Section::Decimate),
            sections,
        }
    }

    /// Whether a mesh of `family` is measured.
    pub fn measures(&self, family: &str) -> bool {
        match family {
            "real" => self.measure_real,
            topolab_harness::scale::FAMILY => self.sections.contains(&Section::RealAtScale),
            _ => self.size_sweep != SizeSweep::None,
        }
    }

    /// Whether a mesh of `family` is measured lightly (construction and the 1-ring sweep); the
    /// refined real meshes never are: they are measured like the tori.
    pub fn light(&self, family: &str) -> bool {
        match family {
            "real" => true,
            topolab_harness::scale::FAMILY => false,
            _ => self.size_sweep == SizeSweep::Light,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_help_of_sections_names_every_section() {
        use clap::CommandFactory as _;
        let cli = crate::cli::Cli::command();
        let report = cli.find_subcommand("report").expect("report");
        let arg = report
            .get_arguments()
            .find(|a| a.get_id() == "sections")
            .expect("--sections");
        let help = arg.get_help().expect("documented").to_string();
        for s in Section::ALL {
            assert!(
                help.contains(s.name()),
                "--sections help lacks {}",
                s.name()
            );
        }
    }

    #[test]
    fn a_focused_run_measures_only_what_its_sections_show() {
        let mut notes = Vec::new();
        let all = Selection::new(None, None, &mut notes);
        assert_eq!(all.sections, Section::ALL);
        assert!(all.libigl && all.hull && all.orderings && all.measures("real"));
        assert_eq!(all.size_sweep, SizeSweep::Full);
        assert!(notes.is_empty());

        let memory = Selection::new(Some(&[Section::Memory]), None, &mut notes);
        assert_eq!(memory.size_sweep, SizeSweep::Light);
        assert!(memory.light("torus") && !memory.measures("real") && !memory.real_meshes);
        assert!(!memory.libigl && !memory.hull && !memory.orderings);

        let real = Selection::new(Some(&[Section::RealMeshes]), None, &mut notes);
        assert!(real.measures("real") && !real.measures("torus") && !real.generated);
        let orders = Selection::new(Some(&[Section::Orderings]), None, &mut notes);
        assert!(orders.generated && !orders.measures("torus"));
        // The element order renumbers a refined mesh without measuring it.
        assert!(orders.refined && !orders.measures("refined"));
        let scale = Selection::new(Some(&[Section::RealAtScale]), None, &mut notes);
        assert!(scale.refined && scale.measures("refined") && !scale.light("refined"));
        assert!(!scale.measures("torus") && !scale.generated && !scale.orderings);
        assert!(!memory.refined);
        let changing = Selection::new(Some(&[Section::Changing]), None, &mut notes);
        assert!(changing.changing && changing.generated && !changing.measures("torus"));
        assert!(!memory.changing);
        let decimate = Selection::new(Some(&[Section::Decimate]), None, &mut notes);
        assert!(decimate.decimate && decimate.generated && !decimate.measures("torus"));
        assert!(!memory.decimate && !changing.decimate);
    }

    #[test]
    fn structures_leave_out_the_libigl_and_hull_sections_they_do_not_name() {
        let mut notes = Vec::new();
        let list = ["che-l2".to_string()];
        let focused = Selection::new(None, Some(&list), &mut notes);
        assert!(!focused.libigl && !focused.hull);
        assert!(!focused.sections.contains(&Section::Hull));
        assert_eq!(notes.len(), 2, "{notes:?}");
        let list = [HULL_STRUCTURE.to_string(), LIBIGL.to_string()];
        let named = Selection::new(
            Some(&[Section::Hull, Section::Libigl]),
            Some(&list),
            &mut notes,
        );
        assert!(named.libigl && named.hull);
    }

    #[test]
    fn an_unknown_section_lists_the_known() {
        let e = section("nope").unwrap_err();
        assert!(e.contains("table-4-1") && e.contains("real-meshes"), "{e}");
        assert_eq!(section("hull"), Ok(Section::Hull));
    }
}
