# Every target bootstraps .venv from nothing but python3.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
NOTEBOOKS := $(sort $(wildcard notebooks/[0-9]*.ipynb))
SOURCES := $(wildcard course tests benchmarks notebooks)
# JupyterLab refuses to start as root without this flag (containers run as root).
ROOT_FLAG := $(if $(filter 0,$(shell id -u)),--allow-root,)

export PYDEVD_DISABLE_FILE_VALIDATION := 1

.PHONY: lab test lint format notebooks bench clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# One stamp per extra, redone when pyproject.toml changes.
$(VENV)/.%-installed: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e ".[$*]"
	touch $@

lab: $(VENV)/.lab-installed $(VENV)/.test-installed
	$(BIN)/jupyter lab notebooks/ $(ROOT_FLAG)

lint: $(VENV)/.test-installed
	$(BIN)/ruff format --check $(SOURCES)
	$(BIN)/ruff check $(SOURCES)

format: $(VENV)/.test-installed
	$(BIN)/ruff format $(SOURCES)
	$(BIN)/ruff check --fix $(SOURCES)

test: lint
	$(BIN)/python -m pytest -n 2 --dist loadfile course tests \
		--nbval --nbval-current-env --nbval-cell-timeout=300 $(NOTEBOOKS)

notebooks: $(VENV)/.test-installed
	for notebook in $(NOTEBOOKS); do \
		$(BIN)/jupyter nbconvert --to notebook --execute --inplace \
			--ExecutePreprocessor.timeout=600 "$$notebook" || exit 1; \
	done
	$(BIN)/nbstripout --keep-output --keep-count $(NOTEBOOKS)

bench: $(VENV)/.bench-installed $(VENV)/.test-installed
	for script in benchmarks/bench_*.py; do $(BIN)/python "$$script" || exit 1; done

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache
