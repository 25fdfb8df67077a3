"""The report generator (issue 7): result files of `silodem verify` / `silodem compare` and the
benchmark JSON -> figures (matplotlib), CSV tables with units, index.html and report.md.
Run it as `/usr/bin/python3 tools/report.py --results results --out reports`."""
