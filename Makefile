# The two set-up commands of README.md:
#   make reproduce   paper-fidelity run of everything that exists
#   make test        the whole test suite, including a quick end-to-end run
# Both create .venv (if missing) and install the package and exactly the dependency versions
# of requirements.lock (hash-checked); `make lock` refreshes the lock from pyproject.toml.

PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: reproduce quick test install lock clean-results slurm-check

$(STAMP): pyproject.toml requirements.lock
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet --require-hashes -r requirements.lock
	$(BIN)/python -m pip install --quiet --no-deps -e .
	touch $(STAMP)

install: $(STAMP)

reproduce: $(STAMP)
	$(BIN)/snakemake

quick: $(STAMP)
	$(BIN)/snakemake --configfile config/quick.yaml

test: $(STAMP)
	$(BIN)/python -m pytest

# installs and starts a single-node SLURM (root, apt), runs a small target of each paper through
# profiles/slurm and locally, checks the outputs are identical, stops SLURM (~5-10 min)
slurm-check: $(STAMP)
	$(BIN)/python -m pip install --quiet -e '.[cluster]'
	bash profiles/slurm/check.sh

# every dependency of pyproject.toml (+ the test extra) pinned with hashes, resolved on PyPI
lock:
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet pip-tools
	PIP_CONFIG_FILE=/dev/null $(BIN)/pip-compile --quiet --generate-hashes --extra test \
		--strip-extras --pip-args "--isolated" -o requirements.lock pyproject.toml

clean-results:
	rm -rf results .snakemake
