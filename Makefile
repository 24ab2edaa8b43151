# Every target bootstraps .venv from nothing but python3 (3.10 or newer) and its venv module,
# and installs the exact versions in requirements/ (see `make lock`). Plain `make` prints help.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
LOCK := requirements
NOTEBOOKS := $(sort $(wildcard notebooks/[0-9]*.ipynb))
# The Chinese lessons: the twins that exist (python -m course twins writes one per catalog).
TWINS = $(sort $(wildcard notebooks/zh-CN/[0-9]*.ipynb))
SOURCES := $(wildcard course tests tests_browser benchmarks notebooks site)
APP_PORT ?= 8866
# JupyterLab refuses to start as root without this flag (containers run as root).
ROOT_FLAG := $(if $(filter 0,$(shell id -u)),--allow-root,)
# Kernel messages sent at once, not held back by Nagle's algorithm (course.classroom.serving).
PROMPT := course.classroom.serving.PromptConnection
# Where `make site` writes the course's website (the student edition: no answers), and
# `make site-teacher` the teacher's, with the answers: never publish that one.
SITE := build/site
TEACHER_SITE := build/site-teacher
# MathJax for the website's formulas: npm's mathjax package, pinned.
MATHJAX_VERSION := 3.2.2
MATHJAX := build/mathjax-$(MATHJAX_VERSION)
# Node.js, for its npm: `make site` fetches MathJax with `npm pack` (any Node.js with npm);
# the hub's proxy comes from `npm ci` in hub/, and configurable-http-proxy 5.3.0 needs
# Node.js 20 or newer (NODE_HUB). On Node.js 20, npm ci warns EBADENGINE for commander 15,
# which asks for 22.12: the proxy imports it as a module, which Node.js 20 runs.
NODE_HUB := 20
# node -e '$(NODE_AT_LEAST)' MINIMUM: exit status 0 when node's version is MINIMUM or newer.
NODE_AT_LEAST = const [a, b] = process.versions.node.split(".").map(Number); \
	const [c, d = 0] = process.argv[1].split(".").map(Number); \
	process.exit(a > c || (a === c && b >= d) ? 0 : 1)
# A recipe line: $(call NODE_CHECK,MINIMUM,TARGET) stops TARGET with a clear message when
# node or npm is missing, or node is older than MINIMUM (MAJOR or MAJOR.MINOR; empty: any).
NODE_CHECK = @node_version=$$(node --version 2>/dev/null); npm_version=$$(npm --version 2>/dev/null); \
	if [ -z "$$node_version" ] || [ -z "$$npm_version" ]; then \
		echo "make $(2): needs Node.js$(if $(1), $(1) or newer) with its npm; node is" \
			"$${node_version:-missing}, npm $${npm_version:-missing}." >&2; \
		echo "  Install Node.js from https://nodejs.org (or your system's nodejs and npm" \
			"packages), then run make $(2) again." >&2; \
		exit 1; \
	fi; \
	if [ -n "$(1)" ] && ! node -e '$(NODE_AT_LEAST)' '$(1)'; then \
		echo "make $(2): needs Node.js $(1) or newer; node is $$node_version ($$(command -v node))." >&2; \
		echo "  Install a newer one (https://nodejs.org, or nvm), first on PATH, then run" \
			"make $(2) again." >&2; \
		exit 1; \
	fi

# The editions' language: `make lab COURSE_LANG=zh-CN` (lab, teach, app, student, nbgrader,
# hub; site builds both languages, test tests both). Not LANG, which every shell sets for its
# own messages. English by default.
COURSE_LANG ?= en
# The folder of a language's edition inside an English one's: nothing for English.
LANG_DIR := $(if $(filter-out en,$(COURSE_LANG)),/$(COURSE_LANG),)
# Where `make nbgrader` writes the nbgrader course folder (build/nbgrader-zh-CN in Chinese).
NBGRADER := build/nbgrader$(subst /,-,$(LANG_DIR))

export PYDEVD_DISABLE_FILE_VALIDATION := 1

.DEFAULT_GOAL := help
.PHONY: help lab teach app student nbgrader site-teacher test test-latest test-browser fuzz lint format notebooks site \
	bench bench-browser hub bench-hub mutants lock clean messages

## help: this list of targets
help:
	@echo "Usage: make TARGET   (each target creates .venv and installs what it needs)"
	@echo
	@sed -n 's/^## \([a-z-]*\): \(.*\)/  \1|\2/p' $(MAKEFILE_LIST) | awk -F'|' '{ printf "%-16s %s\n", $$1, $$2 }'
	@echo
	@echo "Python 3.10 or newer is needed: make lab PYTHON=python3.12 picks another one."
	@echo "中文版: make lab COURSE_LANG=zh-CN (also teach, app, student, nbgrader, hub)."

# The install sets: pyproject.toml's name for each (for `make lock` and `make test-latest`),
# and the lock pip installs from by default. Students get `lab`; `test` is the developer's set;
# `grade` the teacher's nbgrader.
UV_lab := --extra lab
UV_grade := --extra grade
UV_app := --extra app
UV_test := --group pyproject.toml:dev
UV_browser := --extra browser
UV_bench := --extra bench
UV_hub := --extra hub
UV_site := --group pyproject.toml:site
PIP_lab := -e ".[lab]"
PIP_grade := -e ".[grade]"
PIP_app := -e ".[app]"
PIP_test := -e . --group dev
PIP_browser := -e ".[browser]"
PIP_bench := -e ".[bench]"
PIP_hub := -e ".[hub]"
PIP_site := -e . --group site
SETS := lab grade app test browser bench site hub

# Checks before anything is installed: the Python version, then the venv module.
$(BIN)/python:
	@version=$$($(PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null); \
	if ! $(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 10))' 2>/dev/null; then \
		echo "make: the course needs Python 3.10 or newer; '$(PYTHON)' is $${version:-missing}." >&2; \
		echo "  Install Python 3.10 or newer (python.org, or on macOS 'brew install python@3.12')," >&2; \
		echo "  then run for example: make lab PYTHON=python3.12" >&2; \
		exit 1; \
	fi
	@if ! $(PYTHON) -c 'import ensurepip, venv' 2>/dev/null; then \
		echo "make: '$(PYTHON)' has no working venv module (ensurepip is missing)." >&2; \
		echo "  On Debian/Ubuntu: sudo apt install python3-venv   (then run make again)" >&2; \
		exit 1; \
	fi
	@echo "make: creating $(VENV) and installing the course; the first time takes a few minutes."
	$(PYTHON) -m venv $(VENV) || { rm -rf $(VENV); exit 1; }
	$(BIN)/python -m pip install --progress-bar on --upgrade "pip>=25.1"

# One stamp per install set, redone when its lock or pyproject.toml changes. LATEST=1 (as
# `make test-latest` sets it) installs the newest releases instead of the lock.
$(VENV)/.%-installed: $(LOCK)/%.txt pyproject.toml | $(BIN)/python
	@echo "make: installing the '$*' set into $(VENV) $(if $(LATEST),(newest releases),from $(LOCK)/$*.txt)"
	$(BIN)/python -m pip install --progress-bar on \
		$(if $(LATEST),--upgrade --upgrade-strategy eager $(PIP_$*),-r $(LOCK)/$*.txt -e .)
	@# jsonschema imports rfc3987-syntax whenever it is installed (jupyter-events asks for it),
	@# which builds a Lark grammar at import: 2.8 s more for every process that reads a
	@# notebook (each nbgrader command, each Jupyter server). Without it jsonschema only skips
	@# the "iri" formats, which nothing here uses (python-jsonschema/jsonschema#1428).
	$(BIN)/python -m pip uninstall --yes --quiet rfc3987-syntax
	$(BIN)/pybabel compile -d course/locale -D course --statistics
	touch $@

## messages: extract the library's marked strings into course.pot and merge them into the .po
messages: $(VENV)/.test-installed
	$(BIN)/pybabel extract -F babel.cfg --no-wrap --sort-by-file --project course \
		--ignore-dirs "__pycache__" -o course/locale/course.pot course
	$(BIN)/pybabel update --no-wrap --no-fuzzy-matching -i course/locale/course.pot \
		-d course/locale -D course
	$(BIN)/pybabel compile -d course/locale -D course --statistics

## lab: for students: update the student edition in student/, open its course map in JupyterLab
# COURSE_LANG=zh-CN (see COURSE_LANG above): the Chinese edition, student/zh-CN/, notebooks/zh-CN/
# `python -m course lab` writes new and changed lessons into student/, never over one the
# student edited (a changed lesson goes beside it), and adds --allow-root when run as root.
# The servers' lines (lab, teach, app) hold no double quotes nor other shell syntax, so that
# make runs them itself: through sh, Ctrl-C would end with "make: *** [lab] Interrupt".
lab: $(VENV)/.lab-installed
	@echo "make: JupyterLab opens at the course map; its address is printed below, under" \
		"'Or copy and paste one of these URLs'. To stop it: Ctrl-C, then y (or Ctrl-C again)."
	$(BIN)/python -m course lab --language '$(COURSE_LANG)'

## teach: for teachers: the solved lessons in notebooks/, in JupyterLab
teach: $(VENV)/.lab-installed
	$(BIN)/python -m course lab --teacher --language '$(COURSE_LANG)'

## app: the lessons as apps for a projector: Voila, code hidden, sliders live
# python -m course app runs voila on notebooks/ (notebooks/zh-CN/ in Chinese), with $(PROMPT).
app: $(VENV)/.app-installed
	$(BIN)/python -m course app --language '$(COURSE_LANG)' --port $(APP_PORT)

## student: write or update the student edition in student/; a student's edits are kept
student: $(VENV)/.lab-installed
	$(BIN)/python -m course student --language '$(COURSE_LANG)' --out student$(LANG_DIR)

## nbgrader: write the nbgrader course folder build/nbgrader/ (see the README, For teachers)
# Its source/ is rewritten from the lessons; release/, submitted/, the gradebook and an
# nbgrader_config.py already there are left alone.
nbgrader: $(VENV)/.grade-installed
	$(BIN)/python -m course nbgrader --language '$(COURSE_LANG)' --out $(NBGRADER) --force
	@echo "make: the nbgrader course is in $(NBGRADER)/; from there, with .venv/bin on PATH:" \
		"nbgrader generate_assignment 01_de_casteljau"

## lint: ruff's format check and lint, on the pinned ruff
lint: $(VENV)/.test-installed
	$(BIN)/ruff format --check $(SOURCES)
	$(BIN)/ruff check $(SOURCES)

## format: ruff format and ruff check --fix
format: $(VENV)/.test-installed
	$(BIN)/ruff format $(SOURCES)
	$(BIN)/ruff check --fix $(SOURCES)

## test: ruff, unit and property tests, doctests, and every notebook with nbval
test: lint $(VENV)/.hub-installed
	$(BIN)/python -m pytest -n 2 --dist loadfile course tests \
		--nbval --nbval-current-env --nbval-cell-timeout=300 $(NOTEBOOKS) $(TWINS)

## test-latest: make test on the newest releases (in .venv-latest), to find drift first
test-latest:
	$(MAKE) test VENV=.venv-latest LATEST=1

## fuzz: a longer fuzz campaign over every public function, with counts by outcome
fuzz: $(VENV)/.test-installed
	COURSE_FUZZ=long $(BIN)/python -m pytest tests/test_fuzz.py -q -s -n 0 -p no:cacheprovider

## site: build the course's website in build/site/ (Chinese: zh-CN/): the student edition
# Exercises show their stubs; every other cell keeps its committed output (the notebooks are
# not re-executed). MathJax is bundled from its npm package, so formulas render offline.
# The Chinese lessons are a second build into its zh-CN/ folder; every page links its twin.
site: $(VENV)/.site-installed $(MATHJAX)/es5/tex-mml-chtml.js
	$(BIN)/python site/stage.py --mathjax $(MATHJAX)/es5 build/site-source
	$(BIN)/python -m sphinx -b html -q -W --keep-going -c site build/site-source $(SITE)
	$(BIN)/python site/stage.py --language zh-CN --mathjax $(MATHJAX)/es5 build/site-source-zh-CN
	$(BIN)/python -m sphinx -b html -q -W --keep-going -c site -D language=zh_CN \
		build/site-source-zh-CN $(SITE)/zh-CN
	@echo "make: the website is in $(SITE)/; open $(SITE)/index.html ($(SITE)/zh-CN/index.html: 中文)"

# MathJax, fetched once from npm's registry, then served by the site itself.
$(MATHJAX)/es5/tex-mml-chtml.js:
	$(call NODE_CHECK,,site)
	rm -rf $(MATHJAX) && mkdir -p $(MATHJAX)
	cd $(MATHJAX) && npm pack --silent mathjax@$(MATHJAX_VERSION) > /dev/null
	tar -xzf $(MATHJAX)/mathjax-$(MATHJAX_VERSION).tgz -C $(MATHJAX) --strip-components=1
	touch $@

## site-teacher: the website with the answers, in build/site-teacher/: for teachers only
site-teacher: $(VENV)/.site-installed $(MATHJAX)/es5/tex-mml-chtml.js
	$(BIN)/python site/stage.py --teacher --mathjax $(MATHJAX)/es5 build/site-teacher-source
	$(BIN)/python -m sphinx -b html -q -W --keep-going -c site build/site-teacher-source \
		$(TEACHER_SITE)
	$(BIN)/python site/stage.py --teacher --language zh-CN --mathjax $(MATHJAX)/es5 \
		build/site-teacher-source-zh-CN
	$(BIN)/python -m sphinx -b html -q -W --keep-going -c site -D language=zh_CN \
		build/site-teacher-source-zh-CN $(TEACHER_SITE)/zh-CN
	@echo "make: the teacher's website is in $(TEACHER_SITE)/; do not publish it"

## test-browser: build the website, then check its pages and run every lesson in Chromium
# Debian's Chromium (/usr/bin/chromium, installed here if missing, or CHROMIUM=another);
# screenshots in build/screenshots/. Not in `make test`.
CHROMIUM ?= /usr/bin/chromium
export CHROMIUM
# Two workers, each with its own JupyterLab and Voila on free ports: a lesson's kernel
# computes while the other worker's browser waits.
test-browser: site $(VENV)/.browser-installed $(VENV)/.test-installed $(CHROMIUM)
	SITE=$(SITE) $(BIN)/python -m pytest -p no:cacheprovider --timeout=900 --durations=20 -v \
		-n 2 tests_browser

# Only Debian's package is installed for you (as root, or through sudo): elsewhere, install
# Chromium yourself and name it with CHROMIUM.
/usr/bin/chromium:
	@command -v apt-get >/dev/null || { echo "make: $@ is missing and this is not Debian:" \
		"install Chromium and run make CHROMIUM=/path/to/chromium test-browser" >&2; exit 1; }
	$(if $(filter 0,$(shell id -u)),,sudo )env DEBIAN_FRONTEND=noninteractive apt-get update -q
	$(if $(filter 0,$(shell id -u)),,sudo )env DEBIAN_FRONTEND=noninteractive \
		apt-get install -y -q chromium

# The README's picture: lesson 01's app as the notebook first shows it.
README_PICTURE := 01_de_casteljau_degree3_t0.50

## notebooks: re-execute and normalise the lessons, English and Chinese, then the README's table
# A print before a slow line reaches nbclient as two stream outputs, which JupyterLab
# joins when it runs the cell: join them here too, or Run All and save changes the file.
COALESCE = $(BIN)/jupyter nbconvert --to notebook --inplace --log-level=WARN \
	--CoalesceStreamsPreprocessor.enabled=True

# Outputs and counts kept, and each cell's id: the twins' catalogs are keyed by it, so an id
# must survive every save (nbformat 4.5 ids; JupyterLab keeps them too).
STRIP = $(BIN)/nbstripout --keep-output --keep-count --keep-id

notebooks: $(VENV)/.lab-installed $(VENV)/.test-installed
	for notebook in $(NOTEBOOKS); do \
		$(BIN)/jupyter nbconvert --to notebook --execute --inplace \
			--ExecutePreprocessor.timeout=600 "$$notebook" || exit 1; \
	done
	$(COALESCE) $(NOTEBOOKS)
	$(STRIP) $(NOTEBOOKS)
	$(BIN)/python -m course twins
	for notebook in notebooks/zh-CN/[0-9]*.ipynb; do \
		test -e "$$notebook" || continue; \
		$(BIN)/jupyter nbconvert --to notebook --execute --inplace \
			--ExecutePreprocessor.timeout=600 "$$notebook" || exit 1; \
		$(COALESCE) "$$notebook" || exit 1; \
		$(STRIP) "$$notebook" || exit 1; \
	done
	$(BIN)/python -m course map --readme README.md
	$(BIN)/python -m course gallery --out docs --force --only $(README_PICTURE)

# One BLAS thread: every anchor runs on one core, so the ratios compare like with
# like, and a busy machine cannot stall a multithreaded matrix product. Except the
# Poisson benchmark: course.poisson limits its own threads, as it must on a student's
# laptop, and the benchmark measures that quiet and under load, which pinning would hide.
UNPINNED_BENCH := benchmarks/bench_poisson.py
## bench: the performance ratios against the reference implementations
bench: $(VENV)/.bench-installed $(VENV)/.test-installed
	for script in $(filter-out benchmarks/bench_browser_latency.py benchmarks/bench_hub.py \
			benchmarks/bench_mutants.py $(UNPINNED_BENCH),$(wildcard benchmarks/bench_*.py)); do \
		OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1 $(BIN)/python "$$script" || exit 1; \
	done
	for script in $(UNPINNED_BENCH); do $(BIN)/python "$$script" || exit 1; done

## mutants: how many single-slip mutants of each reference solution its checker fails
# Every mutant in a process of its own, two at a time, each under a 20 s timeout: minutes.
# tests/test_mutants.py runs a sample in `make test`; COURSE_MUTANTS=all runs them all.
mutants: $(VENV)/.test-installed
	nice $(BIN)/python benchmarks/bench_mutants.py

## bench-browser: the time from a mouse move or a key press to the new picture, in Chromium
bench-browser: $(VENV)/.browser-installed $(VENV)/.test-installed $(CHROMIUM)
	$(BIN)/python benchmarks/bench_browser_latency.py

# A class on this machine: the hub's state (database, the students' folders, the student
# edition they are seeded from, nbgrader's exchange) and its proxy from npm, pinned by
# hub/package-lock.json and installed in hub/ as docs/hub.md's server steps install it.
HUB_DATA := build/hub
HUB_PORT ?= 8000
HUB_PASSWORD ?= trial
HUB_PROXY := hub/node_modules/.bin/configurable-http-proxy
## hub: a JupyterHub for a trial class at http://127.0.0.1:8000 (any name, password 'trial')
# hub/jupyterhub_config.py is the file a teacher copies to a server (docs/hub.md). The
# edition is rebuilt at each start; a student's folder only ever gains the files it lacks.
# The hub's settings are exported, so that its line holds no shell syntax: make runs it
# itself, and Ctrl-C ends with the hub's own lines, not "make: *** [hub] Interrupt".
hub: export COURSE_HUB_DATA := $(HUB_DATA)
hub: export COURSE_HUB_PORT := $(HUB_PORT)
hub: export COURSE_HUB_PASSWORD := $(HUB_PASSWORD)
hub: $(VENV)/.hub-installed $(HUB_PROXY)
	$(BIN)/python -m course student --language '$(COURSE_LANG)' --out $(HUB_DATA)/student-edition --force
	@echo "make: the hub opens at http://127.0.0.1:$(HUB_PORT); log in with any name and" \
		"the password '$(HUB_PASSWORD)' ('teacher' is the teacher). Stop it with Ctrl-C."
	$(BIN)/jupyterhub -f hub/jupyterhub_config.py

## bench-hub: simulated students on the hub: memory, drag round trips, N = 1 to 30 (minutes)
bench-hub: $(VENV)/.hub-installed $(HUB_PROXY)
	$(BIN)/python benchmarks/bench_hub.py

$(HUB_PROXY): hub/package.json hub/package-lock.json
	$(call NODE_CHECK,$(NODE_HUB),hub)
	cd hub && npm ci --no-audit --no-fund
	touch $@

# uv's `pip compile`, pinned, in the venv. The versions already in the lock are kept unless
# pyproject.toml no longer allows them: `make lock UPGRADE=1` moves every set to the newest.
UV_VERSION := 0.13.9
UV_COMPILE = $(BIN)/uv pip compile --universal --python-version 3.10 --quiet \
	--custom-compile-command "make lock" $(if $(UPGRADE),--upgrade)
$(BIN)/uv: | $(BIN)/python
	$(BIN)/python -m pip install "uv==$(UV_VERSION)"

## lock: regenerate requirements/*.txt (for Python 3.10+ on Linux, macOS and Windows)
# all.txt holds every set at once; each set's lock is resolved within it, so that the sets
# installed into one venv always agree.
lock: $(BIN)/uv
	mkdir -p $(LOCK)
	$(UV_COMPILE) pyproject.toml --all-extras $(UV_test) $(UV_site) -o $(LOCK)/all.txt
	$(foreach set,$(SETS),$(UV_COMPILE) pyproject.toml $(UV_$(set)) -c $(LOCK)/all.txt \
		--annotation-style line -o $(LOCK)/$(set).txt && ) true

## clean: remove the venvs and the caches
clean:
	rm -rf $(VENV) .venv-latest .pytest_cache .ruff_cache
