//! One group of a target's structures taking turns, its structures visited by name from a
//! list of structures ([`First`], then [`Second`]).

use crate::measuring::timing::meter::MemoryMeter;
use crate::targets::plan::{Cell, Turns, PROBE};
use crate::targets::probe::{with_probe, ProbeTurns};
use crate::targets::rounds::pair;
use std::marker::PhantomData;
use topolab_structures::registry::{StructureVisitor, Structures};
use topolab_structures::{MeshTopology, PolygonSoup};

/// What every group's visit needs.
pub struct Case<'a> {
    /// The mesh's name.
    pub mesh: &'a str,
    /// The mesh.
    pub soup: &'a PolygonSoup,
    /// The cells the group is timed on.
    pub cells: &'a [Cell],
    /// What the probe measures in turns with a structure held to its limit.
    pub probe: Option<ProbeTurns>,
    /// The process's meter and clock.
    pub meter: &'a dyn MemoryMeter,
}

/// Visits a group's first structure, then its second (or times the first with the probe).
pub struct First<'a, L> {
    /// The group's second structure (`None` or [`PROBE`]: the probe's turns).
    pub second: Option<&'a str>,
    /// The mesh, cells and probe of the group.
    pub case: &'a Case<'a>,
    /// The list both come from.
    pub list: PhantomData<fn() -> L>,
}

impl<L: Structures> StructureVisitor for First<'_, L> {
    type Output = Result<Vec<Turns>, String>;
    fn visit<A: MeshTopology>(self) -> Self::Output {
        let c = self.case;
        let b = match self.second {
            Some(PROBE) | None => {
                let probe = c.probe.ok_or("no limit to take turns with")?;
                return with_probe::<A>(c.mesh, c.soup, c.cells, probe, c.meter);
            }
            Some(b) => b,
        };
        let second = Second::<A> {
            case: c,
            first: PhantomData,
        };
        L::visit(b, second).map_err(|_| format!("no structure is called {b}"))?
    }
}

/// Times a group's two structures in turns.
pub struct Second<'a, A> {
    case: &'a Case<'a>,
    first: PhantomData<fn() -> A>,
}

impl<A: MeshTopology> StructureVisitor for Second<'_, A> {
    type Output = Result<Vec<Turns>, String>;
    fn visit<B: MeshTopology>(self) -> Self::Output {
        let c = self.case;
        pair::<A, B>(c.mesh, c.soup, c.cells, c.meter)
    }
}
