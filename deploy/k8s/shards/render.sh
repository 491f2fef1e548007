#!/usr/bin/env bash
# Prints the Kubernetes objects of a tile set served by SHARDS shards (2
# replicas each) behind 2 stateless routers, for `kubectl apply -f -`:
#
#   bash deploy/k8s/shards/render.sh 4 | kubectl apply -f -
#
# configmap.yaml as it is; shard.yaml.in once per shard K (its headless
# Service, StatefulSet and PodDisruptionBudget, serving `--tiles K/SHARDS`);
# router.yaml.in with one target per shard's headless Service.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
shards="${1:-4}"
case "$shards" in
  ''|*[!0-9]*|0) echo "usage: render.sh SHARDS (a count >= 1)" >&2; exit 2 ;;
esac

cat "$here/configmap.yaml"
targets=()
for ((k = 0; k < shards; k++)); do
  echo "---"
  sed -e "s/@SHARD@/$k/g" -e "s/@SHARDS@/$shards/g" "$here/shard.yaml.in"
  targets+=("dns:///locator-shard-$k.\$(POD_NAMESPACE).svc.cluster.local:50051")
done
echo "---"
sed -e "s#@SHARD_TARGETS@#$(IFS=,; echo "${targets[*]}")#" "$here/router.yaml.in"
