# The reference blends, one definition for scripts/make-references and scripts/run.
# blend_args NAME: the size options of `sgmp pack` and `sgmp-reference pour` (periodic cell).
# blend_counts NAME: the counts poured. blend_names: every blend.
blend_names() { echo "bimodal trimodal"; }
blend_args() {
    case "$1" in
        bimodal) echo "--size-modes 1:0.5,0.5:0.5 --fraction-basis volume --sides periodic" ;;
        trimodal) echo "--size-modes 1:0.6,0.25:0.2,0.15:0.2 --fraction-basis volume --sides periodic" ;;
        *) return 1 ;;
    esac
}
blend_counts() {
    case "$1" in
        bimodal) echo "1002 3000" ;;
        trimodal) echo "10000 15000" ;;
        *) return 1 ;;
    esac
}
