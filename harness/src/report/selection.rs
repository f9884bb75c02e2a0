//! What a report run measures, from `--sections` and `--structures`: the sections of the page
//! it shows, and what they need measured before them ([`Needs`]); the sections that measure a
//! subject of their own that takes long (libigl, the hull algorithms) run only when
//! `--structures` names it, so that a run focused on a few structures stays quick.

use crate::report::section::{Needs, Real, Refined, Section, SizeSweep};
use crate::report::sections::real_at_scale::FAMILY;
use crate::report::sections::{self, SECTIONS};

/// A section by name (`--sections`); an unknown one lists the known.
pub fn section(name: &str) -> Result<&'static dyn Section, String> {
    sections::by_name(name)
        .ok_or_else(|| format!("unknown section; known: {}", sections::names().join(", ")))
}

/// What a run measures.
#[derive(Clone)]
pub struct Selection {
    /// The sections shown, in page order, each once.
    pub sections: Vec<&'static dyn Section>,
    /// What they need, all together: the most any of them needs of each kind (the subject of
    /// none).
    pub needs: Needs,
}

impl Selection {
    /// The selection of `--sections` by name (`None`: every section; every name known, see
    /// [`section`]) and `--structures` (`None`: every structure, and libigl). Sections that
    /// `--structures` leaves without their subject are dropped with a note in `notes`.
    pub fn new(
        requested: Option<&[String]>,
        structures: Option<&[String]>,
        notes: &mut Vec<String>,
    ) -> Self {
        let asked = |s: &&&dyn Section| requested.is_none_or(|r| r.iter().any(|n| n == s.name()));
        let named = |n: &str| structures.is_none_or(|list| list.iter().any(|s| s == n));
        let mut shown = Vec::new();
        for &s in SECTIONS.iter().filter(asked) {
            match s.needs().subject {
                Some(subject) if !named(subject) => notes.push(format!(
                    "The {} section was not run: --structures does not name {subject}.",
                    s.name()
                )),
                _ => shown.push(s),
            }
        }
        let all = |f: &dyn Fn(Needs) -> bool| shown.iter().any(|s| f(s.needs()));
        let needs = Needs {
            size_sweep: shown
                .iter()
                .map(|s| s.needs().size_sweep)
                .max()
                .unwrap_or(SizeSweep::None),
            generated: all(&|n| n.generated),
            real: shown
                .iter()
                .map(|s| s.needs().real)
                .max()
                .unwrap_or(Real::None),
            refined: shown
                .iter()
                .map(|s| s.needs().refined)
                .max()
                .unwrap_or(Refined::None),
            subject: None,
        };
        Self {
            sections: shown,
            needs,
        }
    }

    /// Whether the section called `name` is shown.
    pub fn shows(&self, name: &str) -> bool {
        self.sections.iter().any(|s| s.name() == name)
    }

    /// The names of the sections shown, in page order.
    pub fn names(&self) -> Vec<&'static str> {
        self.sections.iter().map(|s| s.name()).collect()
    }

    /// Whether the generated meshes are made: for the size sweep, or for a section that
    /// measures on them itself.
    pub fn generated(&self) -> bool {
        self.needs.size_sweep != SizeSweep::None || self.needs.generated
    }

    /// Whether a mesh of `family` is measured.
    pub fn measures(&self, family: &str) -> bool {
        match family {
            "real" => self.needs.real == Real::Measured,
            FAMILY => self.needs.refined == Refined::Measured,
            _ => self.needs.size_sweep != SizeSweep::None,
        }
    }

    /// Whether a mesh of `family` is measured lightly (construction and the 1-ring sweep); the
    /// refined real meshes never are: they are measured like the tori.
    pub fn light(&self, family: &str) -> bool {
        match family {
            "real" => true,
            FAMILY => false,
            _ => self.needs.size_sweep == SizeSweep::Light,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::sections::hull::HULL_STRUCTURE;
    use crate::report::sections::libigl::LIBIGL;

    fn only(names: &[&str]) -> Option<Vec<String>> {
        Some(names.iter().map(|s| s.to_string()).collect())
    }

    #[test]
    fn a_focused_run_measures_only_what_its_sections_show() {
        let mut notes = Vec::new();
        let all = Selection::new(None, None, &mut notes);
        assert_eq!(all.names(), sections::names());
        assert!(all.shows("libigl") && all.shows("hull") && all.measures("real"));
        assert_eq!(all.needs.size_sweep, SizeSweep::Full);
        assert!(notes.is_empty());

        let sel = |names: &[&str], notes: &mut Vec<String>| {
            Selection::new(only(names).as_deref(), None, notes)
        };
        let memory = sel(&["memory"], &mut notes);
        assert_eq!(memory.needs.size_sweep, SizeSweep::Light);
        assert!(memory.light("torus") && !memory.measures("real"));
        assert_eq!(memory.needs.real, Real::None);
        assert_eq!(memory.names(), ["memory"]);

        let real = sel(&["real-meshes"], &mut notes);
        assert!(real.measures("real") && !real.measures("torus") && !real.generated());
        let orders = sel(&["orderings"], &mut notes);
        assert!(orders.generated() && !orders.measures("torus"));
        // The element order renumbers a refined mesh without measuring it.
        assert_eq!(orders.needs.refined, Refined::Made);
        assert!(!orders.measures("refined"));
        let scale = sel(&["real-at-scale"], &mut notes);
        assert!(scale.measures("refined") && !scale.light("refined"));
        assert!(!scale.measures("torus") && !scale.generated());
        assert_eq!(memory.needs.refined, Refined::None);
        for name in ["changing", "decimate"] {
            let s = sel(&[name], &mut notes);
            assert!(s.generated() && !s.measures("torus"), "{name}");
        }
        // Page order, whatever the order asked.
        assert_eq!(
            sel(&["targets", "memory", "chooser"], &mut notes).names(),
            ["chooser", "memory", "targets"]
        );
        assert!(notes.is_empty(), "{notes:?}");
    }

    #[test]
    fn structures_leave_out_the_libigl_and_hull_sections_they_do_not_name() {
        let mut notes = Vec::new();
        let list = ["che-l2".to_string()];
        let focused = Selection::new(None, Some(&list), &mut notes);
        assert!(!focused.shows("libigl") && !focused.shows("hull"));
        assert_eq!(notes.len(), 2, "{notes:?}");
        let list = [HULL_STRUCTURE.to_string(), LIBIGL.to_string()];
        let named = Selection::new(
            only(&["hull", "libigl"]).as_deref(),
            Some(&list),
            &mut notes,
        );
        assert!(named.shows("libigl") && named.shows("hull"));
    }

    #[test]
    fn an_unknown_section_lists_the_known() {
        let e = section("nope").err().expect("unknown");
        assert!(e.contains("table-4-1") && e.contains("real-meshes"), "{e}");
        assert_eq!(section("hull").map(|s| s.name()), Ok("hull"));
    }
}
