//! The report's "reads per query" table and its teaching section (see [`super`]).
