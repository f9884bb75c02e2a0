//! The structures of a list ([`Structures`]) as the report's sections ask for them by name
//! ([`Roster`]).

use crate::measure::{MeshCase, Plan};
use crate::report::run::Roster;
use crate::results::Measurement;
use crate::targets::group::{Case, First};
use crate::targets::plan::Turns;
use std::marker::PhantomData;
use topolab_structures::registry::{StructureVisitor, Structures};
use topolab_structures::{MeshTopology, Operator};

/// The structures of the list `L`, as a [`Roster`].
pub struct Listed<L>(PhantomData<L>);

impl<L> Listed<L> {
    /// The list `L`.
    pub fn new() -> Self {
        Self(PhantomData)
    }
}

impl<L> Default for Listed<L> {
    fn default() -> Self {
        Self::new()
    }
}

struct Sweep<'a> {
    case: &'a MeshCase<'a>,
    plan: &'a Plan,
}

impl StructureVisitor for Sweep<'_> {
    type Output = Result<Measurement, String>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        crate::measure::measure_sweep::<M>(self.case, Operator::R00, self.plan)
    }
}

impl<L: Structures> Roster for Listed<L> {
    fn sweep(
        &self,
        name: &str,
        case: &MeshCase,
        plan: &Plan,
    ) -> Option<Result<Measurement, String>> {
        L::visit(name, Sweep { case, plan }).ok()
    }

    fn targets(
        &self,
        first: &str,
        second: Option<&str>,
        case: &Case,
    ) -> Option<Result<Vec<Turns>, String>> {
        let visitor = First::<L> {
            second,
            case,
            list: PhantomData,
        };
        L::visit(first, visitor).ok()
    }
}
