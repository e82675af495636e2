

module gpu_regs(clock,host$aw_valid,host$aw_ready,host$aw_addr,host$w_valid,host$w_ready,host$w_data,host$w_strb,host$b_valid,host$b_ready,host$b_resp,host$ar_valid,host$ar_ready,host$ar_addr,host$r_valid,host$r_ready,host$r_data,host$r_resp,status,frame_cycles,triangles,done,start,clear,irq,vb_addr,color_base,color_pitch,depth_base,depth_pitch,screen);
    
    // Module arguments
    input wire  clock;
    input wire  host$aw_valid;
    output reg  host$aw_ready;
    input wire  [5:0] host$aw_addr;
    input wire  host$w_valid;
    output reg  host$w_ready;
    input wire  [31:0] host$w_data;
    input wire  [3:0] host$w_strb;
    output reg  host$b_valid;
    input wire  host$b_ready;
    output reg  [1:0] host$b_resp;
    input wire  host$ar_valid;
    output reg  host$ar_ready;
    input wire  [5:0] host$ar_addr;
    output reg  host$r_valid;
    input wire  host$r_ready;
    output reg  [31:0] host$r_data;
    output reg  [1:0] host$r_resp;
    input wire  [31:0] status;
    input wire  [31:0] frame_cycles;
    input wire  [31:0] triangles;
    input wire  done;
    output reg  start;
    output reg  clear;
    output reg  irq;
    output reg  [31:0] vb_addr;
    output reg  [31:0] color_base;
    output reg  [15:0] color_pitch;
    output reg  [31:0] depth_base;
    output reg  [15:0] depth_pitch;
    output reg  [31:0] screen;
    
    // Stub signals
    reg  [2:0] control$d;
    wire  [2:0] control$q;
    reg  control$clock;
    reg  [31:0] vb$d;
    wire  [31:0] vb$q;
    reg  vb$clock;
    reg  [31:0] cbase$d;
    wire  [31:0] cbase$q;
    reg  cbase$clock;
    reg  [15:0] cpitch$d;
    wire  [15:0] cpitch$q;
    reg  cpitch$clock;
    reg  [31:0] zbase$d;
    wire  [31:0] zbase$q;
    reg  zbase$clock;
    reg  [15:0] zpitch$d;
    wire  [15:0] zpitch$q;
    reg  zpitch$clock;
    reg  [31:0] screen_r$d;
    wire  [31:0] screen_r$q;
    reg  screen_r$clock;
    reg  start_r$d;
    wire  start_r$q;
    reg  start_r$clock;
    reg  pending$d;
    wire  pending$q;
    reg  pending$clock;
    reg  b_valid$d;
    wire  b_valid$q;
    reg  b_valid$clock;
    reg  [1:0] b_resp$d;
    wire  [1:0] b_resp$q;
    reg  b_resp$clock;
    reg  r_valid$d;
    wire  r_valid$q;
    reg  r_valid$clock;
    reg  [31:0] r_data$d;
    wire  [31:0] r_data$q;
    reg  r_data$clock;
    reg  [1:0] r_resp$d;
    wire  [1:0] r_resp$q;
    reg  r_resp$clock;
    wire  [31:0] ident$id;
    
    // Local signals
    reg  write;
    reg  [3:0] wi;
    reg  [31:0] mask;
    reg  [31:0] merged;
    reg  [3:0] ri;
    
    // Sub module instances
    gpu_regs$control control(
        .d(control$d),
        .q(control$q),
        .clock(control$clock)
    );
    gpu_regs$vb vb(
        .d(vb$d),
        .q(vb$q),
        .clock(vb$clock)
    );
    gpu_regs$cbase cbase(
        .d(cbase$d),
        .q(cbase$q),
        .clock(cbase$clock)
    );
    gpu_regs$cpitch cpitch(
        .d(cpitch$d),
        .q(cpitch$q),
        .clock(cpitch$clock)
    );
    gpu_regs$zbase zbase(
        .d(zbase$d),
        .q(zbase$q),
        .clock(zbase$clock)
    );
    gpu_regs$zpitch zpitch(
        .d(zpitch$d),
        .q(zpitch$q),
        .clock(zpitch$clock)
    );
    gpu_regs$screen_r screen_r(
        .d(screen_r$d),
        .q(screen_r$q),
        .clock(screen_r$clock)
    );
    gpu_regs$start_r start_r(
        .d(start_r$d),
        .q(start_r$q),
        .clock(start_r$clock)
    );
    gpu_regs$pending pending(
        .d(pending$d),
        .q(pending$q),
        .clock(pending$clock)
    );
    gpu_regs$b_valid b_valid(
        .d(b_valid$d),
        .q(b_valid$q),
        .clock(b_valid$clock)
    );
    gpu_regs$b_resp b_resp(
        .d(b_resp$d),
        .q(b_resp$q),
        .clock(b_resp$clock)
    );
    gpu_regs$r_valid r_valid(
        .d(r_valid$d),
        .q(r_valid$q),
        .clock(r_valid$clock)
    );
    gpu_regs$r_data r_data(
        .d(r_data$d),
        .q(r_data$q),
        .clock(r_data$clock)
    );
    gpu_regs$r_resp r_resp(
        .d(r_resp$d),
        .q(r_resp$q),
        .clock(r_resp$clock)
    );
    gpu_regs$ident ident(
        .id(ident$id)
    );
    
    // Update code
    always @(*) begin
        control$clock = clock;
        vb$clock = clock;
        cbase$clock = clock;
        cpitch$clock = clock;
        zbase$clock = clock;
        zpitch$clock = clock;
        screen_r$clock = clock;
        start_r$clock = clock;
        pending$clock = clock;
        b_valid$clock = clock;
        b_resp$clock = clock;
        r_valid$clock = clock;
        r_data$clock = clock;
        r_resp$clock = clock;
        control$d = control$q;
        vb$d = vb$q;
        cbase$d = cbase$q;
        cpitch$d = cpitch$q;
        zbase$d = zbase$q;
        zpitch$d = zpitch$q;
        screen_r$d = screen_r$q;
        start_r$d = start_r$q;
        pending$d = pending$q;
        b_valid$d = b_valid$q;
        b_resp$d = b_resp$q;
        r_valid$d = r_valid$q;
        r_data$d = r_data$q;
        r_resp$d = r_resp$q;
        start = start_r$q;
        clear = control$q[32'h1];
        irq = control$q[32'h2] & pending$q;
        vb_addr = vb$q;
        color_base = cbase$q;
        color_pitch = cpitch$q;
        depth_base = zbase$q;
        depth_pitch = zpitch$q;
        screen = screen_r$q;
        host$b_valid = b_valid$q;
        host$b_resp = b_resp$q;
        host$r_valid = r_valid$q;
        host$r_data = r_data$q;
        host$r_resp = r_resp$q;
        host$ar_ready = ~r_valid$q;
        write = ~b_valid$q & host$aw_valid & host$w_valid;
        host$aw_ready = write;
        host$w_ready = write;
        wi = host$aw_addr[(32'h2)+:(4)];
        merged = 32'h0;
        mask = 32'h0;
        mask = (mask & ~(1 << (32'h8 * 0 + 0)) | ((host$w_strb[0]) << (32'h8 * 0 + 0)));
        mask = (mask & ~(1 << (32'h8 * 0 + 1)) | ((host$w_strb[0]) << (32'h8 * 0 + 1)));
        mask = (mask & ~(1 << (32'h8 * 0 + 2)) | ((host$w_strb[0]) << (32'h8 * 0 + 2)));
        mask = (mask & ~(1 << (32'h8 * 0 + 3)) | ((host$w_strb[0]) << (32'h8 * 0 + 3)));
        mask = (mask & ~(1 << (32'h8 * 0 + 4)) | ((host$w_strb[0]) << (32'h8 * 0 + 4)));
        mask = (mask & ~(1 << (32'h8 * 0 + 5)) | ((host$w_strb[0]) << (32'h8 * 0 + 5)));
        mask = (mask & ~(1 << (32'h8 * 0 + 6)) | ((host$w_strb[0]) << (32'h8 * 0 + 6)));
        mask = (mask & ~(1 << (32'h8 * 0 + 7)) | ((host$w_strb[0]) << (32'h8 * 0 + 7)));
        mask = (mask & ~(1 << (32'h8 * 1 + 0)) | ((host$w_strb[1]) << (32'h8 * 1 + 0)));
        mask = (mask & ~(1 << (32'h8 * 1 + 1)) | ((host$w_strb[1]) << (32'h8 * 1 + 1)));
        mask = (mask & ~(1 << (32'h8 * 1 + 2)) | ((host$w_strb[1]) << (32'h8 * 1 + 2)));
        mask = (mask & ~(1 << (32'h8 * 1 + 3)) | ((host$w_strb[1]) << (32'h8 * 1 + 3)));
        mask = (mask & ~(1 << (32'h8 * 1 + 4)) | ((host$w_strb[1]) << (32'h8 * 1 + 4)));
        mask = (mask & ~(1 << (32'h8 * 1 + 5)) | ((host$w_strb[1]) << (32'h8 * 1 + 5)));
        mask = (mask & ~(1 << (32'h8 * 1 + 6)) | ((host$w_strb[1]) << (32'h8 * 1 + 6)));
        mask = (mask & ~(1 << (32'h8 * 1 + 7)) | ((host$w_strb[1]) << (32'h8 * 1 + 7)));
        mask = (mask & ~(1 << (32'h8 * 2 + 0)) | ((host$w_strb[2]) << (32'h8 * 2 + 0)));
        mask = (mask & ~(1 << (32'h8 * 2 + 1)) | ((host$w_strb[2]) << (32'h8 * 2 + 1)));
        mask = (mask & ~(1 << (32'h8 * 2 + 2)) | ((host$w_strb[2]) << (32'h8 * 2 + 2)));
        mask = (mask & ~(1 << (32'h8 * 2 + 3)) | ((host$w_strb[2]) << (32'h8 * 2 + 3)));
        mask = (mask & ~(1 << (32'h8 * 2 + 4)) | ((host$w_strb[2]) << (32'h8 * 2 + 4)));
        mask = (mask & ~(1 << (32'h8 * 2 + 5)) | ((host$w_strb[2]) << (32'h8 * 2 + 5)));
        mask = (mask & ~(1 << (32'h8 * 2 + 6)) | ((host$w_strb[2]) << (32'h8 * 2 + 6)));
        mask = (mask & ~(1 << (32'h8 * 2 + 7)) | ((host$w_strb[2]) << (32'h8 * 2 + 7)));
        mask = (mask & ~(1 << (32'h8 * 3 + 0)) | ((host$w_strb[3]) << (32'h8 * 3 + 0)));
        mask = (mask & ~(1 << (32'h8 * 3 + 1)) | ((host$w_strb[3]) << (32'h8 * 3 + 1)));
        mask = (mask & ~(1 << (32'h8 * 3 + 2)) | ((host$w_strb[3]) << (32'h8 * 3 + 2)));
        mask = (mask & ~(1 << (32'h8 * 3 + 3)) | ((host$w_strb[3]) << (32'h8 * 3 + 3)));
        mask = (mask & ~(1 << (32'h8 * 3 + 4)) | ((host$w_strb[3]) << (32'h8 * 3 + 4)));
        mask = (mask & ~(1 << (32'h8 * 3 + 5)) | ((host$w_strb[3]) << (32'h8 * 3 + 5)));
        mask = (mask & ~(1 << (32'h8 * 3 + 6)) | ((host$w_strb[3]) << (32'h8 * 3 + 6)));
        mask = (mask & ~(1 << (32'h8 * 3 + 7)) | ((host$w_strb[3]) << (32'h8 * 3 + 7)));
        start_r$d = 1'b0;
        pending$d = pending$q | done;
        if (b_valid$q & host$b_ready) begin
            b_valid$d = 1'b0;
        end
        if (write) begin
            b_valid$d = 1'b1;
            b_resp$d = 32'h0;
            if (wi > 32'hb) begin
                b_resp$d = 32'h2;
            end
            if (wi == 32'h1) begin
                merged = (((control$q) & 32'hffffffff) & ~mask) | (host$w_data & mask);
                control$d = (merged[(32'h0)+:(3)] & ~(1 << (32'h0)) | ((1'b0) << (32'h0)));
                start_r$d = merged[32'h0];
            end
            if ((wi == 32'h3) & mask[32'h0] & host$w_data[32'h0] & ~done) begin
                pending$d = 1'b0;
            end
            if (wi == 32'h4) begin
                vb$d = (vb$q & ~mask) | (host$w_data & mask);
            end
            if (wi == 32'h5) begin
                cbase$d = (cbase$q & ~mask) | (host$w_data & mask);
            end
            if (wi == 32'h6) begin
                merged = (((cpitch$q) & 32'hffffffff) & ~mask) | (host$w_data & mask);
                cpitch$d = merged[(32'h0)+:(16)];
            end
            if (wi == 32'h7) begin
                zbase$d = (zbase$q & ~mask) | (host$w_data & mask);
            end
            if (wi == 32'h8) begin
                merged = (((zpitch$q) & 32'hffffffff) & ~mask) | (host$w_data & mask);
                zpitch$d = merged[(32'h0)+:(16)];
            end
            if (wi == 32'hb) begin
                screen_r$d = (screen_r$q & ~mask) | (host$w_data & mask);
            end
        end
        ri = host$ar_addr[(32'h2)+:(4)];
        if (r_valid$q & host$r_ready) begin
            r_valid$d = 1'b0;
        end
        if (~r_valid$q & host$ar_valid) begin
            r_valid$d = 1'b1;
            r_resp$d = 32'h0;
            r_data$d = 32'h0;
            if (ri == 32'h0) begin
                r_data$d = ident$id;
            end
            if (ri == 32'h1) begin
                r_data$d = ((control$q) & 32'hffffffff);
            end
            if (ri == 32'h2) begin
                r_data$d = status;
            end
            if ((ri == 32'h3) & pending$q) begin
                r_data$d = 32'h1;
            end
            if (ri == 32'h4) begin
                r_data$d = vb$q;
            end
            if (ri == 32'h5) begin
                r_data$d = cbase$q;
            end
            if (ri == 32'h6) begin
                r_data$d = ((cpitch$q) & 32'hffffffff);
            end
            if (ri == 32'h7) begin
                r_data$d = zbase$q;
            end
            if (ri == 32'h8) begin
                r_data$d = ((zpitch$q) & 32'hffffffff);
            end
            if (ri == 32'h9) begin
                r_data$d = frame_cycles;
            end
            if (ri == 32'ha) begin
                r_data$d = triangles;
            end
            if (ri == 32'hb) begin
                r_data$d = screen_r$q;
            end
            if (ri > 32'hb) begin
                r_resp$d = 32'h2;
            end
        end
    end
    
endmodule // gpu_regs


module gpu_regs$b_resp(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$b_resp


module gpu_regs$b_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$b_valid


module gpu_regs$cbase(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$cbase


module gpu_regs$control(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$control


module gpu_regs$cpitch(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$cpitch


module gpu_regs$ident(id);
    
    // Module arguments
    output reg  [31:0] id;
    
    // Constant declarations
    localparam  value = 32'h4550020a;
    
    // Update code
    always @(*) begin
        id = value;
    end
    
endmodule // gpu_regs$ident


module gpu_regs$pending(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$pending


module gpu_regs$r_data(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$r_data


module gpu_regs$r_resp(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$r_resp


module gpu_regs$r_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$r_valid


module gpu_regs$screen_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$screen_r


module gpu_regs$start_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$start_r


module gpu_regs$vb(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$vb


module gpu_regs$zbase(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$zbase


module gpu_regs$zpitch(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // gpu_regs$zpitch
