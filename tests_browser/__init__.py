"""Browser tests: the lessons in JupyterLab and Voila, in Chromium (make test-browser)."""
