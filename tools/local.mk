# SPDX-License-Identifier: MIT
# Command-line tools and benchmark programs.
