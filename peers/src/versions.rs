//! The exact versions of the crates this build measures, pinned in `peers/Cargo.toml`
//! (Cargo.lock records their checksums): what each adapter names as its crate's version.

/// lox's version, pinned in `peers/Cargo.toml`.
pub const LOX_VERSION: &str = "0.1.1";
/// baby_shark's version, pinned in `peers/Cargo.toml`.
pub const BABY_SHARK_VERSION: &str = "0.3.12";
/// tri-mesh's version, pinned in `peers/Cargo.toml`.
pub const TRI_MESH_VERSION: &str = "0.6.1";
