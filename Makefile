# The two set-up commands of README.md:
#   make reproduce   paper-fidelity run of everything that exists
#   make test        the whole test suite, including a quick end-to-end run
# Both create .venv (if missing) and install the package and its dependencies.

PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: reproduce quick test install clean-results slurm-check

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
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

clean-results:
	rm -rf results .snakemake
