"""python -m strew.cli"""

import sys

from . import main

sys.exit(main())
