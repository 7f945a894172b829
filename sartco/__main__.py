import sys

from sartco.cli import main

sys.exit(main())
