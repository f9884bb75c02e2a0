//! `--sections` of `topolab report`: the names of the page's sections, from the harness's one
//! list of them ([`topolab_harness::report::sections::SECTIONS`]); what a run measures for
//! them is the harness's [`Selection`](topolab_harness::report::selection::Selection).

use topolab_harness::report::selection;

/// A section's name checked against the list (`--sections`); an unknown one lists the known.
pub fn section(name: &str) -> Result<String, String> {
    selection::section(name).map(|s| s.name().to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_harness::report::sections;

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
        for s in sections::names() {
            assert!(help.contains(s), "--sections help lacks {s}");
        }
    }

    #[test]
    fn an_unknown_section_lists_the_known() {
        let e = section("nope").unwrap_err();
        assert!(e.contains("table-4-1") && e.contains("real-meshes"), "{e}");
        assert_eq!(section("hull").as_deref(), Ok("hull"));
    }
}
