"""The optimal oracle: the gold plan of a dataset task and the policy that follows it."""
