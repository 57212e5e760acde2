import sys

from assistantx.cli import main

sys.exit(main())
