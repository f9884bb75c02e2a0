//! Build script of the `topolab` package: sets the cfgs of the baselines that
//! `topolab-baselines` compiled in (`has_openmesh`, `has_cgal`, `has_cgal_decimate`,
//! `has_qhull`, `has_cpp_heap`), which its build script passes up through `links` metadata, so
//! that the commands, examples and tests that name a baseline's types compile without it.

/// Every cfg `topolab-baselines` may pass.
const CFGS: [&str; 5] = [
    "has_openmesh",
    "has_cgal",
    "has_cgal_decimate",
    "has_qhull",
    "has_cpp_heap",
];

fn main() {
    for cfg in CFGS {
        println!("cargo::rustc-check-cfg=cfg({cfg})");
    }
    println!("cargo::rerun-if-env-changed=DEP_TOPOLAB_BASELINES_CFGS");
    let passed = std::env::var("DEP_TOPOLAB_BASELINES_CFGS").unwrap_or_default();
    for cfg in passed.split(',').filter(|c| CFGS.contains(c)) {
        println!("cargo::rustc-cfg={cfg}");
    }
}
