# Every target bootstraps .venv from nothing but python3.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
NOTEBOOKS := $(sort $(wildcard notebooks/[0-9]*.ipynb))
SOURCES := $(wildcard course tests tests_browser benchmarks notebooks)
APP_PORT ?= 8866
# JupyterLab refuses to start as root without this flag (containers run as root).
ROOT_FLAG := $(if $(filter 0,$(shell id -u)),--allow-root,)
# Kernel messages sent at once, not held back by Nagle's algorithm (course.classroom.serving).
PROMPT := course.classroom.serving.PromptConnection

export PYDEVD_DISABLE_FILE_VALIDATION := 1

.PHONY: lab app student test test-browser lint format notebooks bench bench-browser clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# One stamp per extra, redone when pyproject.toml changes.
$(VENV)/.%-installed: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e ".[$*]"
	touch $@

# The lessons in JupyterLab, opened at the course map, with student/ beside notebooks/ so a
# teacher can open the student edition in the same session. It is written only if missing:
# work a student saved there is never overwritten (`make student` rewrites it).
lab: $(VENV)/.lab-installed $(VENV)/.test-installed
	test -d student || $(BIN)/python -m course student --out student
	$(BIN)/jupyter lab --ServerApp.root_dir=. \
		--LabApp.default_url=/lab/tree/notebooks/00_index.ipynb \
		$(ROOT_FLAG) --ServerApp.kernel_websocket_connection_class=$(PROMPT)

# The lessons as apps for a lecture hall: Voila, code hidden, sliders live.
app: $(VENV)/.lab-installed $(VENV)/.test-installed
	$(BIN)/voila notebooks/ --no-browser --Voila.ip=127.0.0.1 --port=$(APP_PORT) \
		--Voila.kernel_websocket_connection_class=$(PROMPT)

# The student edition: solutions replaced by stubs, outputs cleared, in student/.
student: $(VENV)/.test-installed
	$(BIN)/python -m course student --out student --force

lint: $(VENV)/.test-installed
	$(BIN)/ruff format --check $(SOURCES)
	$(BIN)/ruff check $(SOURCES)

format: $(VENV)/.test-installed
	$(BIN)/ruff format $(SOURCES)
	$(BIN)/ruff check --fix $(SOURCES)

test: lint
	$(BIN)/python -m pytest -n 2 --dist loadfile course tests \
		--nbval --nbval-current-env --nbval-cell-timeout=300 $(NOTEBOOKS)

# Every notebook run in JupyterLab and one through Voila, in Debian's Chromium
# (/usr/bin/chromium); screenshots in build/screenshots/. Not part of `make test`.
test-browser: $(VENV)/.browser-installed $(VENV)/.test-installed
	$(BIN)/python -m pytest -p no:cacheprovider --timeout=900 --durations=0 -v tests_browser

# The README's picture: lesson 01's app as the notebook first shows it.
README_PICTURE := 01_de_casteljau_degree3_t0.50

notebooks: $(VENV)/.test-installed
	for notebook in $(NOTEBOOKS); do \
		$(BIN)/jupyter nbconvert --to notebook --execute --inplace \
			--ExecutePreprocessor.timeout=600 "$$notebook" || exit 1; \
	done
	$(BIN)/nbstripout --keep-output --keep-count $(NOTEBOOKS)
	$(BIN)/python -m course map --readme README.md
	$(BIN)/python -m course gallery --out docs --force --only $(README_PICTURE)

# One BLAS thread: every anchor runs on one core, so the ratios compare like with
# like, and a busy machine cannot stall a multithreaded matrix product. Except the
# Poisson benchmark: course.poisson limits its own threads, as it must on a student's
# laptop, and the benchmark measures that quiet and under load, which pinning would hide.
UNPINNED_BENCH := benchmarks/bench_poisson.py
bench: $(VENV)/.bench-installed $(VENV)/.test-installed
	for script in $(filter-out benchmarks/bench_browser_latency.py $(UNPINNED_BENCH),$(wildcard benchmarks/bench_*.py)); do \
		OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1 $(BIN)/python "$$script" || exit 1; \
	done
	for script in $(UNPINNED_BENCH); do $(BIN)/python "$$script" || exit 1; done

# The time from a mouse move or a key press to the new picture, in JupyterLab in
# Debian's Chromium, against an echo app's floor. Not part of `make test`.
bench-browser: $(VENV)/.browser-installed $(VENV)/.test-installed
	$(BIN)/python benchmarks/bench_browser_latency.py

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache
