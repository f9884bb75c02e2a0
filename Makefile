# The two commands a new user types are `make report` and `make test` (see README.md).
# Both are idempotent and install what is missing first.

CARGO ?= cargo

.PHONY: deps test report check-format

# Installs system and Python packages the lab uses, where this machine allows it.
deps:
	@bash .ci/install-deps

# Every test of the workspace.
test: deps
	$(CARGO) test --workspace

# The report on the default meshes: reports/latest/index.html and results.json.
report: deps
	$(CARGO) run --release --quiet -- report
