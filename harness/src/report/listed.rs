//! The structures of a list ([`Structures`]) as the report's sections ask for them by name
//! ([`Roster`]).

use crate::measuring::rounds::{SetUp, Setup};
use crate::report::run::Roster;
use crate::targets::group::{Case, First};
use crate::targets::plan::Turns;
use std::marker::PhantomData;
use topolab_structures::registry::Structures;

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

impl<L: Structures> Roster for Listed<L> {
    fn set_up<'a>(&self, name: &str, set_up: SetUp<'a, '_>) -> Option<Result<Setup<'a>, String>> {
        L::visit(name, set_up).ok()
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
